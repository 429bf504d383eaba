// `essaim bench scale`: the avoidance scenario at 1 000, 10 000, 100 000 robots and constant
// density; what each robot-step costs as the swarm grows (bench/README.md).
#pragma once
#include <string>
#include <vector>

namespace essaim {

struct BenchScaleArgs {
  std::string dir;  // holds avoidance_1000.argos
  std::vector<long long> sizes = {1000, 10000, 100000};
  long long ticks = 50;   // timed ticks per run
  long long warmup = 20;  // ticks run before the timed ones, untimed (the Lua states' first collections)
  int threads = 0;        // the second real-time factor's thread count; 0: the hardware's
};

/// Prints one row per size; returns the exit code.
int BenchScale(const BenchScaleArgs& a);

}  // namespace essaim
