// SIGINT and SIGTERM (what SLURM and Dask send) for one command, and the end of a process
// whose Lua call is stuck inside a C function.
#pragma once
#include <atomic>
#include <string>

namespace essaim {

class Watchdog;

/// From Listen() until it goes, SIGINT and SIGTERM are noted here (Caught(): the signal's
/// number, 0 while none) and `watchdog` is asked to stop the Lua call in progress.
class SignalCatcher {
 public:
  explicit SignalCatcher(Watchdog* watchdog) : watchdog_(watchdog) {}
  ~SignalCatcher();
  SignalCatcher(const SignalCatcher&) = delete;
  SignalCatcher& operator=(const SignalCatcher&) = delete;

  void Listen();
  int Caught() const { return caught_.load(); }
  const std::atomic<int>& CaughtFlag() const { return caught_; }

 private:
  static void OnSignal(int sig);

  Watchdog* watchdog_;
  std::atomic<int> caught_{0};
};

/// A watchdog's last resort when nothing is left to write: prints "essaim: <message>" and
/// ends the process with exit 1 (the stuck call cannot be unwound).
[[noreturn]] void ExitStuck(const std::string& message);

}  // namespace essaim
