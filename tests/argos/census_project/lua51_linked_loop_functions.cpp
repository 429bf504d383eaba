#include <argos3/core/simulator/loop_functions.h>

using namespace argos;

extern "C" int lua_gettop(void* L);

class CLua51LinkedLoopFunctions : public CLoopFunctions {
 public:
  void PostStep() override { lua_gettop(nullptr); }
};

REGISTER_LOOP_FUNCTIONS(CLua51LinkedLoopFunctions, "lua51_linked_loop_functions")
