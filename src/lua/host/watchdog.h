// The thread that watches a run's Lua calls: it arms the count hook of calls that run long,
// flags wall-clock overruns and interrupt requests, and reports a call stuck inside a C
// function. One per run, made by whoever runs (the CLI, the Python module, the World when
// given none) and outliving every state that uses it.
//
// It never walks the states: each thread that calls into Lua has one slot here, where a
// guarded call says which state runs for as long as it runs. The monitor looks at the
// slots only, so its cost follows the number of threads, not of robots.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace essaim {

struct LuaGuard;

/// One thread's current guarded call: the state inside it, or null between calls.
struct WatchSlot {
  std::thread::id thread;
  std::atomic<LuaGuard*> guard{nullptr};
};

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

  /// The calling thread's slot, made on its first call (a thread-local cache after that:
  /// no lock per call).
  WatchSlot* ThisThreadSlot();
  /// Returns once the monitor has finished any look at `guard`: a state is closed only
  /// after this (O(1), the monitor's pass is short).
  void Forget(const LuaGuard* guard);

  /// Asks every state to stop at its next hook (calls running over kArmAfterSeconds).
  /// Async-signal-safe: one lock-free store, for SIGINT/SIGTERM handlers.
  void Interrupt() { interrupt_.store(true, std::memory_order_relaxed); }
  bool Interrupted() const { return interrupt_.load(std::memory_order_relaxed); }
  /// The first stuck call's message, "" while none: the status the run reads.
  std::string Stuck() const;
  /// How many threads have a slot (for the tests).
  size_t Slots() const;

 private:
  void Loop();

  const uint64_t id_;  // unique per process: the thread-local cache's key
  StuckHandler on_stuck_;
  std::atomic<bool> interrupt_{false};
  static_assert(std::atomic<bool>::is_always_lock_free, "Interrupt() is called from signal handlers");
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::deque<WatchSlot> slots_;  // a deque: slots never move
  std::string stuck_;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace essaim
