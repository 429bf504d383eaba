// ARGoS's CFootBotGripperDefaultActuator (argos3/plugins/robots/foot-bot/simulator/footbot_gripper_default_actuator.h):
// the <footbot_gripper implementation="default"> actuator a C++ controller's GetActuator returns. The aperture set goes
// to the robot after each controller call.
#pragma once
#include <argos3/core/simulator/actuator.h>
#include <argos3/core/simulator/entity/entity.h>  // ARGoS: through gripper_equipped_entity.h
#include <argos3/core/utility/math/quaternion.h>  // ARGoS: through gripper_equipped_entity.h
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_gripper_actuator.h>

namespace argos {

class CFootBotGripperDefaultActuator : public CCI_FootBotGripperActuator, public CSimulatedActuator {
 public:
  void EnableCheckForObjectGrippedRoutine() override {}
  void DisableCheckForObjectGrippedRoutine() override {}
  /// Hands the aperture to the robot when it changed.
  void Update() override;
  void Reset() override;

 private:
  Real m_fSent = 0;
};

}  // namespace argos
