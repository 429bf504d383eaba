// ARGoS's CFootBotDistanceScannerRotZOnlySensor
// (argos3/plugins/robots/foot-bot/simulator/footbot_distance_scanner_rotzonly_sensor.h): the <footbot_distance_scanner
// implementation="rot_z_only"> sensor a C++ controller's GetSensor returns. Enabled from the start; the maps hold this
// tick's readings.
#pragma once
#include <argos3/core/simulator/entity/embodied_entity.h>
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_sensor.h>

#include <vector>

namespace argos {

class CFootBotDistanceScannerRotZOnlySensor : public CCI_FootBotDistanceScannerSensor, public CSimulatedSensor {
 public:
  void Update() override;
  void Reset() override;

 private:
  void Recycle(TReadingsMap& t_map);
  void Put(TReadingsMap& t_map, const CRadians& c_angle, Real f_distance);
  std::vector<TReadingsMap::node_type> m_vecNodes;  // the maps' nodes, kept from tick to tick
};

}  // namespace argos
