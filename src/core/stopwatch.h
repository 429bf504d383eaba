// Wall-clock seconds for the timings a run reports (set-up and stage seconds): never an
// input to what a run computes.
#pragma once
#include <time.h>

#include <chrono>

namespace essaim {

inline double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// CPU seconds the process has used, summed over its threads: what a benchmark on a
/// machine shared with other work reports beside the wall time.
inline double ProcessCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace essaim
