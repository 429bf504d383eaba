#include <argos3/core/simulator/loop_functions.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

#include <cstddef>

using namespace argos;

// Lua 5.1's lua.h declares these; Lua 5.4 has lua_rawlen instead of lua_objlen.
extern "C" {
struct lua_State;
size_t lua_objlen(lua_State* L, int idx);
}

class CLua51LoopFunctions : public CLoopFunctions {
 public:
  void PostStep() override { lua_objlen(nullptr, 1); }
};

REGISTER_LOOP_FUNCTIONS(CLua51LoopFunctions, "lua51_headers_loop_functions")
