// arenas/clustering_loop.lua in C++: the floor is black inside the zone; Init scatters the
// cylinders in a ring around it, each with a red LED; a cylinder in the zone turns blue, one
// pushed back out red; every `every` ticks a row of timeseries.csv; the run ends once all
// are in; PostExperiment writes metrics.json. Both files go to <output dir="..."> (the
// folder the test gives as --out, so they sit beside the Lua twin's).
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/simulator/simulator.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/core/wrappers/lua/lua_controller.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <argos3/plugins/simulator/entities/box_entity.h>
#include <argos3/plugins/simulator/entities/cylinder_entity.h>
#include <argos3/plugins/simulator/media/led_medium.h>

#include <fstream>
#include <unordered_map>
#include <vector>

using namespace argos;

class CClusteringLoopFunctions : public CLoopFunctions {
 public:
  void Init(TConfigurationNode& t_tree) override {
    TConfigurationNode& tZone = GetNode(t_tree, "zone");
    GetNodeAttribute(tZone, "x", m_fZoneX);
    GetNodeAttribute(tZone, "y", m_fZoneY);
    GetNodeAttribute(tZone, "radius", m_fZoneRadius);
    TConfigurationNode& tCylinders = GetNode(t_tree, "cylinders");
    GetNodeAttribute(tCylinders, "count", m_unCount);
    GetNodeAttribute(tCylinders, "radius", m_fRadius);
    GetNodeAttribute(tCylinders, "height", m_fHeight);
    GetNodeAttribute(tCylinders, "mass", m_fMass);
    GetNodeAttribute(tCylinders, "min_distance", m_fMinDistance);
    GetNodeAttribute(tCylinders, "max_distance", m_fMaxDistance);
    GetNodeAttributeOrDefault(GetNode(t_tree, "output"), "every", m_unEvery, m_unEvery);
    GetNodeAttributeOrDefault(GetNode(t_tree, "output"), "dir", m_strDir, m_strDir);
    m_pcRNG = CRandom::CreateRNG("argos");
    CLEDMedium& cLEDs = GetSimulator().GetMedium<CLEDMedium>("leds");
    for (UInt32 i = 1; i <= m_unCount; ++i) {
      CCylinderEntity* pcCylinder =
          new CCylinderEntity("load" + ToString(i), FreeSpot(), CQuaternion(), true, m_fRadius, m_fHeight, m_fMass);
      pcCylinder->GetLEDEquippedEntity().AddLED(CVector3(0, 0, m_fHeight), CColor::RED);
      pcCylinder->GetLEDEquippedEntity().AddToMedium(cLEDs);
      AddEntity(*pcCylinder);
    }
  }

  CColor GetFloorColor(const CVector2& c_position) override {
    return InZone(c_position.GetX(), c_position.GetY()) ? CColor::BLACK : CColor::WHITE;
  }

  void PostStep() override {
    const UInt32 unTick = GetSpace().GetSimulationClock();
    UInt32 unInZone = 0;
    CSpace::TMapPerType& cCylinders = GetSpace().GetEntitiesByType("cylinder");
    for (CSpace::TMapPerType::iterator it = cCylinders.begin(); it != cCylinders.end(); ++it) {
      CCylinderEntity& cCylinder = *any_cast<CCylinderEntity*>(it->second);
      const CVector3& cPos = cCylinder.GetEmbodiedEntity().GetOriginAnchor().Position;
      const bool bInside = InZone(cPos.GetX(), cPos.GetY());
      bool& bArrived = m_mapArrived[cCylinder.GetId()];
      if (bInside && !bArrived) {
        cCylinder.GetLEDEquippedEntity().SetAllLEDsColors(CColor::BLUE);
        if (m_mapEver[cCylinder.GetId()]++ == 0) m_vecDeliveryTicks.push_back(unTick);
      } else if (!bInside && bArrived) {
        cCylinder.GetLEDEquippedEntity().SetAllLEDsColors(CColor::RED);
      }
      bArrived = bInside;
      if (bInside) ++unInZone;
    }
    if (unInZone == m_unCount && m_unAllDeliveredTick == 0) m_unAllDeliveredTick = unTick;
    if (m_unEvery > 0 && unTick % m_unEvery == 0) m_vecRows.push_back({unTick, unInZone, RobotDeliveries()});
  }

  bool IsExperimentFinished() override { return m_unAllDeliveredTick != 0; }

  void PostExperiment() override {
    UInt32 unInZone = 0;
    for (std::unordered_map<std::string, bool>::iterator it = m_mapArrived.begin(); it != m_mapArrived.end(); ++it)
      unInZone += it->second;
    // As the Lua twin's table: keys in sorted order, the two ticks absent until they happen.
    std::ofstream cMetrics((m_strDir + "/cpp_metrics.json").c_str());
    cMetrics << "{";
    if (m_unAllDeliveredTick != 0) cMetrics << "\"all_delivered_tick\": " << m_unAllDeliveredTick << ", ";
    cMetrics << "\"cylinders\": " << m_unCount << ", \"delivery_ticks\": [";
    for (size_t i = 0; i < m_vecDeliveryTicks.size(); ++i) cMetrics << (i ? ", " : "") << m_vecDeliveryTicks[i];
    cMetrics << "], ";
    if (!m_vecDeliveryTicks.empty()) cMetrics << "\"first_delivery_tick\": " << m_vecDeliveryTicks[0] << ", ";
    cMetrics << "\"in_zone\": " << unInZone << ", \"robot_deliveries\": " << RobotDeliveries() << "}\n";
    std::ofstream cSeries((m_strDir + "/cpp_timeseries.csv").c_str());
    cSeries << "tick,in_zone,robot_deliveries\n";
    for (size_t i = 0; i < m_vecRows.size(); ++i)
      cSeries << m_vecRows[i][0] << "," << m_vecRows[i][1] << "," << m_vecRows[i][2] << "\n";
  }

 private:
  bool InZone(Real f_x, Real f_y) const {
    return (f_x - m_fZoneX) * (f_x - m_fZoneX) + (f_y - m_fZoneY) * (f_y - m_fZoneY) < m_fZoneRadius * m_fZoneRadius;
  }

  // A spot in the ring clear of every entity placed so far (a few tries, then the last).
  CVector3 FreeSpot() {
    Real fX = 0, fY = 0;
    for (int i = 0; i < 100; ++i) {
      const Real fAngle = m_pcRNG->Uniform(CRange<Real>(0, 2 * ARGOS_PI));
      const Real fDistance = m_pcRNG->Uniform(CRange<Real>(m_fMinDistance, m_fMaxDistance));
      fX = m_fZoneX + fDistance * std::cos(fAngle);
      fY = m_fZoneY + fDistance * std::sin(fAngle);
      if (Clear(fX, fY)) break;
    }
    return CVector3(fX, fY, 0);
  }

  bool Clear(Real f_x, Real f_y) {
    const char* pchTypes[] = {"foot-bot", "box", "cylinder"};
    for (const char* pchType : pchTypes) {
      CSpace::TMapPerType* pcEntities = nullptr;
      try {
        pcEntities = &GetSpace().GetEntitiesByType(pchType);
      } catch (CARGoSException&) {
        continue;  // no entity of that type yet
      }
      for (CSpace::TMapPerType::iterator it = pcEntities->begin(); it != pcEntities->end(); ++it)
        if (TooClose(it->second, pchType, f_x, f_y)) return false;
    }
    return true;
  }

  static bool TooClose(CAny& c_entity, const std::string& str_type, Real f_x, Real f_y) {
    CVector3 cPos;
    if (str_type == "foot-bot")
      cPos = any_cast<CFootBotEntity*>(c_entity)->GetEmbodiedEntity().GetOriginAnchor().Position;
    else if (str_type == "box")
      cPos = any_cast<CBoxEntity*>(c_entity)->GetEmbodiedEntity().GetOriginAnchor().Position;
    else
      cPos = any_cast<CCylinderEntity*>(c_entity)->GetEmbodiedEntity().GetOriginAnchor().Position;
    return (cPos.GetX() - f_x) * (cPos.GetX() - f_x) + (cPos.GetY() - f_y) * (cPos.GetY() - f_y) < 0.25 * 0.25;
  }

  // The robots' own delivery counters (their Lua global `deliveries`).
  UInt32 RobotDeliveries() {
    Real fSum = 0;
    CSpace::TMapPerType& cRobots = GetSpace().GetEntitiesByType("foot-bot");
    for (CSpace::TMapPerType::iterator it = cRobots.begin(); it != cRobots.end(); ++it) {
      CFootBotEntity& cRobot = *any_cast<CFootBotEntity*>(it->second);
      CLuaController& cController = dynamic_cast<CLuaController&>(cRobot.GetControllableEntity().GetController());
      lua_State* L = nullptr;
      try {
        L = cController.GetLuaState();
      } catch (CARGoSException&) {
        continue;  // closed after its memory limit: no state (the Lua twin's nil)
      }
      lua_getglobal(L, "deliveries");
      if (lua_isnumber(L, -1)) fSum += lua_tonumber(L, -1);
      lua_pop(L, 1);
    }
    return static_cast<UInt32>(fSum);
  }

  Real m_fZoneX = 0, m_fZoneY = 0, m_fZoneRadius = 0.5;
  UInt32 m_unCount = 0;
  Real m_fRadius = 0, m_fHeight = 0, m_fMass = 0, m_fMinDistance = 0, m_fMaxDistance = 0;
  UInt32 m_unEvery = 50;
  std::string m_strDir = ".";
  CRandom::CRNG* m_pcRNG = nullptr;
  std::unordered_map<std::string, bool> m_mapArrived;
  std::unordered_map<std::string, int> m_mapEver;
  std::vector<UInt32> m_vecDeliveryTicks;
  UInt32 m_unAllDeliveredTick = 0;
  std::vector<std::vector<UInt32> > m_vecRows;
};

REGISTER_LOOP_FUNCTIONS(CClusteringLoopFunctions, "clustering_loop_functions")
