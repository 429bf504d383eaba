// ARGoS's CFootBotDistanceScannerDefaultActuator
// (argos3/plugins/robots/foot-bot/simulator/footbot_distance_scanner_default_actuator.h): the <footbot_distance_scanner
// implementation="default"> actuator a C++ controller's GetActuator returns. Each call is the Lua table's function of
// the same name.
#pragma once
#include <argos3/core/simulator/actuator.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_actuator.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

namespace argos {

class CFootBotDistanceScannerDefaultActuator : public CCI_FootBotDistanceScannerActuator, public CSimulatedActuator {
 public:
  void SetAngle(const CRadians& c_angle) override;
  void SetRPM(Real f_rpm) override;
  void Enable() override;
  void Disable() override;
  void Reset() override;
};

}  // namespace argos
