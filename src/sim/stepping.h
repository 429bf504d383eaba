// Which controller this thread is running, for the one report a crash can still make: a
// C++ controller that faults (a segfault in user code) takes the process down, and the handler
// (app/crash_report.cpp) runs on the faulting thread, where it reads this. Two stores around
// each call; nothing else reads it.
#pragma once
#include <cstdint>

namespace essaim {

constexpr int kSteppingNone = -1;
constexpr int kSteppingLoopFunctions = -2;

struct Stepping {
  int robot = kSteppingNone;  // a robot index, or one of the constants above
  const char* call = "";      // "Init", "ControlStep", "Destroy", or a loop-function hook
};

/// This thread's record (thread_local).
Stepping& ThisThreadStepping();

/// Marks `robot` (and `call`) as running on this thread for the scope.
class SteppingScope {
 public:
  SteppingScope(int robot, const char* call) : saved_(ThisThreadStepping()) { ThisThreadStepping() = {robot, call}; }
  ~SteppingScope() { ThisThreadStepping() = saved_; }
  SteppingScope(const SteppingScope&) = delete;
  SteppingScope& operator=(const SteppingScope&) = delete;

 private:
  Stepping saved_;
};

}  // namespace essaim
