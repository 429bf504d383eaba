// Wall-clock seconds for the timings a run reports (set-up and stage seconds): never an
// input to what a run computes.
#pragma once
#include <chrono>

namespace essaim {

inline double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace essaim
