/* A zone read in Init() and painted black by GetFloorColor; robots' ground readings logged;
   Destroy() reads each robot's `steps` from its Lua state. */
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/wrappers/lua/lua_controller.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

using namespace argos;

class CLifecycleLoopFunctions : public CLoopFunctions {
 public:
  /* The constructor's zone lies outside the arena: a floor drawn from it is all white. */
  CLifecycleLoopFunctions() : m_cZoneCenter(100, 100), m_fZoneRadius(0) {}

  virtual void Init(TConfigurationNode& t_tree) {
    TConfigurationNode& tZone = GetNode(t_tree, "zone");
    GetNodeAttribute(tZone, "center", m_cZoneCenter);
    GetNodeAttribute(tZone, "radius", m_fZoneRadius);
    LOG << "lifecycle: zone at " << m_cZoneCenter << " radius " << m_fZoneRadius << std::endl;
  }

  virtual CColor GetFloorColor(const CVector2& c_position) {
    return (c_position - m_cZoneCenter).Length() < m_fZoneRadius ? CColor::BLACK : CColor::WHITE;
  }

  virtual void Destroy() {
    CSpace::TMapPerType& cBots = GetSpace().GetEntitiesByType("foot-bot");
    for (CSpace::TMapPerType::iterator it = cBots.begin(); it != cBots.end(); ++it) {
      CFootBotEntity& cBot = *any_cast<CFootBotEntity*>(it->second);
      lua_State* ptState = dynamic_cast<CLuaController&>(cBot.GetControllableEntity().GetController()).GetLuaState();
      lua_getglobal(ptState, "steps");
      LOG << "lifecycle: destroy " << cBot.GetId() << " steps " << lua_tonumber(ptState, -1) << std::endl;
      lua_pop(ptState, 1);
    }
  }

 private:
  CVector2 m_cZoneCenter;
  Real m_fZoneRadius;
};

/* Logged while the library loads, before any experiment hook runs. */
static bool bAnnounced = (LOG << "lifecycle: library loaded" << std::endl, true);

REGISTER_LOOP_FUNCTIONS(CLifecycleLoopFunctions, "lifecycle_loop_functions")
