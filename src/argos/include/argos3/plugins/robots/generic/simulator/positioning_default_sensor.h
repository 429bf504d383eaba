// ARGoS's CPositioningDefaultSensor (argos3/plugins/robots/generic/simulator/positioning_default_sensor.h): the
// <positioning implementation="default"> sensor a C++ controller's GetSensor returns. Enabled from the start.
#pragma once
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/math/range.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/generic/control_interface/ci_positioning_sensor.h>

namespace argos {

class CPositioningDefaultSensor : public CCI_PositioningSensor, public CSimulatedSensor {
 public:
  void Update() override;
  void Reset() override;
};

}  // namespace argos
