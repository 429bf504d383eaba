// ARGoS's CFootBotLightRotZOnlySensor (argos3/plugins/robots/foot-bot/simulator/footbot_light_rotzonly_sensor.h): the
// <footbot_light implementation="rot_z_only"> sensor a C++ controller's GetSensor returns. Enabled from the start.
#pragma once
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/math/range.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_light_sensor.h>

namespace argos {

class CFootBotLightRotZOnlySensor : public CCI_FootBotLightSensor, public CSimulatedSensor {
 public:
  void Update() override;
  void Reset() override;
};

}  // namespace argos
