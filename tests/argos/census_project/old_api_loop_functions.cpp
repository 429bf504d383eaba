#include <argos3/core/simulator/loop_functions.h>

using namespace argos;

class COldApiLoopFunctions : public CLoopFunctions {};

// What REGISTER_LOOP_FUNCTIONS expands to in a header of another API version.
namespace {
const bool registered = RegisterLoopFunctions(
    "old_api_loop_functions", []() -> CLoopFunctions* { return new COldApiLoopFunctions; }, 0);
}
