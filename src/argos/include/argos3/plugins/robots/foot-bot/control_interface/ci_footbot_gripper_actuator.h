// ARGoS's CCI_FootBotGripperActuator
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_gripper_actuator.h): the
// gripper's aperture, locked at +pi/2 or -pi/2, unlocked at 0.
#pragma once
#include <argos3/core/control_interface/ci_actuator.h>
#include <argos3/core/utility/math/angles.h>

namespace argos {

class CCI_FootBotGripperActuator : virtual public CCI_Actuator {
 public:
  static CRadians UNLOCKED;
  static CRadians LOCKED_POSITIVE;
  static CRadians LOCKED_NEGATIVE;

  CCI_FootBotGripperActuator() : m_cAperture(0.0) {}
  virtual ~CCI_FootBotGripperActuator() {}
  /// Normalised to [-pi, pi], then kept within [LOCKED_NEGATIVE, LOCKED_POSITIVE].
  void SetAperture(const CRadians& c_aperture);
  virtual void EnableCheckForObjectGrippedRoutine() = 0;
  virtual void DisableCheckForObjectGrippedRoutine() = 0;
  void LockPositive() { SetAperture(LOCKED_POSITIVE); }
  void LockNegative() { SetAperture(LOCKED_NEGATIVE); }
  void Unlock() { SetAperture(UNLOCKED); }

 protected:
  CRadians m_cAperture;
};

}  // namespace argos
