/* Reads each robot's `steps` from its Lua state at the end: this compiles only against the
   Lua headers FindLua52/FindLua53 gave. */
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/wrappers/lua/lua_controller.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

using namespace argos;

class COldModulesLoopFunctions : public CLoopFunctions {
 public:
  virtual void PostExperiment() {
    CSpace::TMapPerType& cBots = GetSpace().GetEntitiesByType("foot-bot");
    for (CSpace::TMapPerType::iterator it = cBots.begin(); it != cBots.end(); ++it) {
      CFootBotEntity& cBot = *any_cast<CFootBotEntity*>(it->second);
      CLuaController* pcLua = dynamic_cast<CLuaController*>(&cBot.GetControllableEntity().GetController());
      if (pcLua == NULL) continue; /* a C++ controller (old_modules_controller.cpp) */
      lua_State* ptState = pcLua->GetLuaState();
      lua_getglobal(ptState, "steps");
      LOG << "old modules: " << cBot.GetId() << " steps " << lua_tonumber(ptState, -1) << std::endl;
      lua_pop(ptState, 1);
    }
  }
};

REGISTER_LOOP_FUNCTIONS(COldModulesLoopFunctions, "old_modules_loop_functions")
