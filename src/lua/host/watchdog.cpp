#include "lua/host/watchdog.h"

#include <algorithm>
#include <chrono>

#include "lua/host/guard_hook.h"

namespace essaim {

Watchdog::Watchdog(StuckHandler on_stuck) : on_stuck_(std::move(on_stuck)), thread_([this] { Loop(); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void Watchdog::Register(LuaGuard* guard) {
  std::lock_guard<std::mutex> lock(mutex_);
  guards_.push_back(guard);
}

void Watchdog::Unregister(LuaGuard* guard) {
  std::lock_guard<std::mutex> lock(mutex_);
  guards_.erase(std::remove(guards_.begin(), guards_.end(), guard), guards_.end());
}

std::string Watchdog::Stuck() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stuck_;
}

void Watchdog::Loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(50), [this] { return stopping_; })) {
    const long long now = SteadyNowNs();
    for (LuaGuard* g : guards_) {
      std::string stuck = WatchGuard(g, now, Interrupted());
      if (stuck.empty()) continue;
      if (stuck_.empty()) stuck_ = stuck;
      // Under the lock, as the states cannot go while their owner's thread is stuck.
      if (on_stuck_) on_stuck_(stuck);
    }
  }
}

}  // namespace essaim
