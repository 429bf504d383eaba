// ARGoS's CDifferentialSteeringDefaultActuator
// (argos3/plugins/robots/generic/simulator/differential_steering_default_actuator.h): the <differential_steering
// implementation="default"> actuator a C++ controller's GetActuator returns. Velocities go to the robot as they are
// set.
#pragma once
#include <argos3/core/simulator/actuator.h>
#include <argos3/core/simulator/entity/composable_entity.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>

namespace argos {

class CDifferentialSteeringDefaultActuator : public CCI_DifferentialSteeringActuator, public CSimulatedActuator {
 public:
  CDifferentialSteeringDefaultActuator() { m_fCurrentVelocity[0] = m_fCurrentVelocity[1] = 0; }
  /// Throws when either velocity is not finite (the robot would not move as asked).
  void SetLinearVelocity(Real f_left_velocity, Real f_right_velocity) override;
  void Reset() override;
};

}  // namespace argos
