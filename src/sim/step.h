// One tick in ARGoS's order, one short function per stage in step.cpp, each timed into
// World::times:
//   1. tick += 1
//   2. act: each robot's actuators apply the commands its controller set last tick
//   3. physics: `iterations` sub-steps, then per-robot component updates (battery...)
//   4. media: who hears whom, where LEDs are
//   5. loop functions pre_step()
//   6. sense + control: per robot, sensors fill readings, then Lua step() (threads split
//      robots here, never the order of stages)
//   7. controllers' logs flushed in robot order, their errors collected
//   8. loop functions post_step(), is_experiment_finished()
// So step() at tick k sees the world after k physics ticks, and its commands act during
// tick k+1: one tick of command latency, as ARGoS.
#pragma once
#include "sim/world.h"

namespace essaim {

enum class StepStatus { Running, Finished, Failed };

StepStatus Step(World& world);
/// True when the experiment length is reached (length 0 = unlimited).
bool LengthReached(const World& world);

}  // namespace essaim
