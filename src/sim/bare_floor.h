// The floor of a run's cost: the controllers' own step() time in bare Lua, on
// the very readings they get in a real run. A simulator can only add to it; `essaim bench
// --floor` prints a run's wall time over this floor.
#pragma once
#include <string>

#include "model/model.h"

namespace essaim {

/// Two floors, from two bare states per robot replayed on the same readings: one on Lua's
/// stock allocator ("bare Lua 5.4", the definition), one on the run's own allocator
/// (lua_guard's small-block pool), which isolates what the simulator adds.
struct BareFloor {
  double step_seconds = 0;       // sum of the bare step() calls, wall clock, stock allocator
  double step_cpu_seconds = 0;   // the same, this thread's CPU time (robust on a busy machine)
  double pool_step_seconds = 0;  // the same two on the run's allocator
  double pool_step_cpu_seconds = 0;
  long long robot_steps = 0;
  long long ticks = 0;
};

/// Runs the experiment (its length, one thread) and, after each tick, replays every robot's
/// readings of that tick through the same script in a bare lua_State of its own
/// (lua/robot/bare_controller.h): the readings are pushed into its tables first, untimed, then
/// only the step() calls are timed. Recording and replay go tick by tick, so the readings
/// never need storing. False with `error` if a script fails to load or raises.
bool MeasureBareFloor(const Model& model, BareFloor* out, std::string* error);

}  // namespace essaim
