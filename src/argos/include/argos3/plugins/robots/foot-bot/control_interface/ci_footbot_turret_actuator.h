// ARGoS's CCI_FootBotTurretActuator
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_turret_actuator.h): the
// turret's mode, and its rotation (position control) or speed (speed control).
#pragma once
#include <argos3/core/control_interface/ci_actuator.h>
#include <argos3/core/utility/math/angles.h>

namespace argos {

class CCI_FootBotTurretActuator : virtual public CCI_Actuator {
 public:
  enum ETurretModes { MODE_OFF, MODE_PASSIVE, MODE_SPEED_CONTROL, MODE_POSITION_CONTROL };

  static const CRange<SInt32> SPEED_RANGE;
  static const CRange<Real> NORMALIZED_SPEED_RANGE;

  virtual ~CCI_FootBotTurretActuator() {}
  virtual void SetRotation(const CRadians& c_angle) = 0;
  virtual void SetRotationSpeed(SInt32 n_speed_pulses) = 0;
  virtual void SetMode(ETurretModes e_mode) = 0;
  void SetActiveWithRotation(const CRadians& c_angle) {
    SetPositionControlMode();
    SetRotation(c_angle);
  }
  void SetSpeedControlMode() { SetMode(MODE_SPEED_CONTROL); }
  void SetPositionControlMode() { SetMode(MODE_POSITION_CONTROL); }
  void SetPassiveMode() { SetMode(MODE_PASSIVE); }
};

}  // namespace argos
