// The thread that watches a run's Lua states: it arms the count hook of calls that run
// long, flags wall-clock overruns and interrupt requests, and reports a call stuck inside a
// C function. One per run, made by whoever runs (the CLI, the Python module, the World when
// given none) and outliving every state registered with it.
#pragma once
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace essaim {

struct LuaGuard;

class Watchdog {
 public:
  /// Receives the message of a call stuck inside a C function (from the watchdog thread).
  /// Such a call cannot be unwound: the run is over, and only the owner knows how to end
  /// it (write what it can, print, exit).
  using StuckHandler = std::function<void(const std::string& message)>;

  explicit Watchdog(StuckHandler on_stuck = nullptr);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  void Register(LuaGuard* guard);
  void Unregister(LuaGuard* guard);

  /// Asks every state to stop at its next hook (calls running over kArmAfterSeconds).
  /// Async-signal-safe: one lock-free store, for SIGINT/SIGTERM handlers.
  void Interrupt() { interrupt_.store(true, std::memory_order_relaxed); }
  bool Interrupted() const { return interrupt_.load(std::memory_order_relaxed); }
  /// The first stuck call's message, "" while none: the status the run reads.
  std::string Stuck() const;

 private:
  void Loop();

  StuckHandler on_stuck_;
  std::atomic<bool> interrupt_{false};
  static_assert(std::atomic<bool>::is_always_lock_free, "Interrupt() is called from signal handlers");
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::vector<LuaGuard*> guards_;
  std::string stuck_;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace essaim
