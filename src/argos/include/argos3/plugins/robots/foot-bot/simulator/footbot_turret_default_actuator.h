// ARGoS's CFootBotTurretDefaultActuator (argos3/plugins/robots/foot-bot/simulator/footbot_turret_default_actuator.h):
// the <footbot_turret implementation="default"> actuator a C++ controller's GetActuator returns. Each call is the Lua
// table's function of the same name.
#pragma once
#include <argos3/core/simulator/actuator.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_turret_actuator.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

namespace argos {

class CFootBotTurretDefaultActuator : public CCI_FootBotTurretActuator, public CSimulatedActuator {
 public:
  void SetRotation(const CRadians& c_angle) override;
  void SetRotationSpeed(SInt32 n_speed_pulses) override;
  void SetMode(ETurretModes e_mode) override;
  void Reset() override;
};

}  // namespace argos
