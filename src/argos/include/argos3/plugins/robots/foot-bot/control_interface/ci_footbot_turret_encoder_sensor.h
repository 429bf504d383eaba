// ARGoS's CCI_FootBotTurretEncoderSensor
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_turret_encoder_sensor.h): the
// turret's rotation, in [-pi, pi].
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/math/vector2.h>

namespace argos {

class CCI_FootBotTurretEncoderSensor : virtual public CCI_Sensor {
 public:
  static const CRange<CRadians> ANGULAR_RANGE;

  virtual ~CCI_FootBotTurretEncoderSensor() {}
  const CRadians& GetRotation() const { return m_cRotation; }

 protected:
  CRadians m_cRotation;
};

}  // namespace argos
