#include <argos3/core/simulator/loop_functions.h>

using namespace argos;

class CLua51NoCallsLoopFunctions : public CLoopFunctions {
 public:
  bool IsExperimentFinished() override { return GetSpace().GetSimulationClock() >= 2; }
};

REGISTER_LOOP_FUNCTIONS(CLua51NoCallsLoopFunctions, "lua51_no_calls_loop_functions")
