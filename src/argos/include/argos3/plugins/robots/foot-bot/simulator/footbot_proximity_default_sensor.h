// ARGoS's CFootBotProximityDefaultSensor (argos3/plugins/robots/foot-bot/simulator/footbot_proximity_default_sensor.h):
// the <footbot_proximity implementation="default"> sensor a C++ controller's GetSensor returns. Updates whether or not
// it is enabled (ARGoS's reads through an inner sensor that enables itself), so IsEnabled() stays false until the
// controller calls Enable().
#pragma once
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/simulator/space/space.h>  // ARGoS: through proximity_default_sensor.h
#include <argos3/core/utility/math/rng.h>       // ARGoS: through proximity_default_sensor.h
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>

namespace argos {

class CFootBotProximityDefaultSensor : public CCI_FootBotProximitySensor, public CSimulatedSensor {
 public:
  void Update() override;
};

}  // namespace argos
