// ARGoS's CCI_DifferentialSteeringActuator
// (argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h): the
// wheels' target velocities.
#pragma once
#include <argos3/core/control_interface/ci_actuator.h>

namespace argos {

class CCI_DifferentialSteeringActuator : public CCI_Actuator {
 public:
  virtual ~CCI_DifferentialSteeringActuator() {}
  /// Left and right wheel velocities, in cm/s.
  virtual void SetLinearVelocity(Real f_left_velocity, Real f_right_velocity) = 0;

 protected:
  Real m_fCurrentVelocity[2];  // m/s, as ARGoS keeps them
};

}  // namespace argos
