// ARGoS's CFootBotTurretEncoderDefaultSensor
// (argos3/plugins/robots/foot-bot/simulator/footbot_turret_encoder_default_sensor.h): the <footbot_turret_encoder
// implementation="default"> sensor a C++ controller's GetSensor returns. Enabled from the start.
#pragma once
#include <argos3/core/simulator/entity/entity.h>  // ARGoS: through footbot_turret_entity.h
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/utility/math/vector3.h>  // ARGoS: through footbot_turret_entity.h
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_turret_encoder_sensor.h>

namespace argos {

class CFootBotTurretEncoderDefaultSensor : public CCI_FootBotTurretEncoderSensor, public CSimulatedSensor {
 public:
  void Update() override;
  void Reset() override;
};

}  // namespace argos
