// ARGoS's CRangeAndBearingMediumSensor (argos3/plugins/robots/generic/simulator/range_and_bearing_medium_sensor.h): the
// <range_and_bearing implementation="medium"> sensor a C++ controller's GetSensor returns. Enabled from the start; the
// packets' data buffers are reused from tick to tick.
#pragma once
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h>

namespace argos {

class CRangeAndBearingMediumSensor : public CCI_RangeAndBearingSensor, public CSimulatedSensor {
 public:
  void Update() override;
  void Reset() override;

 private:
  TReadings m_tSpare;  // packets of earlier ticks not needed now, kept with their buffers
};

}  // namespace argos
