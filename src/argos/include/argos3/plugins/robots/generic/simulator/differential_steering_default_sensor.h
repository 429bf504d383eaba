// ARGoS's CDifferentialSteeringDefaultSensor
// (argos3/plugins/robots/generic/simulator/differential_steering_default_sensor.h): the <differential_steering
// implementation="default"> sensor a C++ controller's GetSensor returns. Enabled from the start.
#pragma once
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/math/range.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_sensor.h>

namespace argos {

class CDifferentialSteeringDefaultSensor : public CCI_DifferentialSteeringSensor, public CSimulatedSensor {
 public:
  void Update() override;
  void Reset() override;
};

}  // namespace argos
