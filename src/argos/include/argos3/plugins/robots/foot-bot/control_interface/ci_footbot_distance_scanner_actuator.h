// ARGoS's CCI_FootBotDistanceScannerActuator
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_actuator.h):
// the scanner's rotation, at a fixed angle or a speed in rpm, switched on and off.
#pragma once
#include <argos3/core/control_interface/ci_actuator.h>
#include <argos3/core/utility/math/angles.h>

namespace argos {

class CCI_FootBotDistanceScannerActuator : virtual public CCI_Actuator {
 public:
  virtual ~CCI_FootBotDistanceScannerActuator() {}
  virtual void SetAngle(const CRadians& c_angle) = 0;
  virtual void SetRPM(Real f_rpm) = 0;
  virtual void Enable() = 0;
  virtual void Disable() = 0;
};

}  // namespace argos
