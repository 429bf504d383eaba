#include "lua/host/watchdog.h"

#include <chrono>

#include "lua/host/guard_hook.h"

namespace essaim {

namespace {
// Ids, not addresses, key the thread-local cache: a watchdog made where a gone one lived
// must not find that one's slots.
std::atomic<uint64_t> next_watchdog_id{1};
}  // namespace

Watchdog::Watchdog(StuckHandler on_stuck)
    : id_(next_watchdog_id.fetch_add(1, std::memory_order_relaxed)),
      on_stuck_(std::move(on_stuck)),
      thread_([this] { Loop(); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

WatchSlot* Watchdog::ThisThreadSlot() {
  thread_local uint64_t cached_id = 0;
  thread_local WatchSlot* cached = nullptr;
  if (cached_id == id_) return cached;
  const std::thread::id me = std::this_thread::get_id();
  std::lock_guard<std::mutex> lock(mutex_);
  WatchSlot* slot = nullptr;
  for (WatchSlot& s : slots_)
    if (s.thread == me) slot = &s;
  if (!slot) {
    // A thread gone and its id reused: its slot is free (null between calls), so shared.
    slot = &slots_.emplace_back();
    slot->thread = me;
  }
  cached_id = id_;
  cached = slot;
  return slot;
}

void Watchdog::Forget(const LuaGuard*) {
  // The monitor reads states only under mutex_, during a pass: once the lock is ours, no
  // pass is looking, and a call that ended left its slot before the state was closed.
  std::lock_guard<std::mutex> lock(mutex_);
}

std::string Watchdog::Stuck() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stuck_;
}

size_t Watchdog::Slots() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return slots_.size();
}

void Watchdog::Loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(10), [this] { return stopping_; })) {
    const long long now = SteadyNowNs();
    for (WatchSlot& slot : slots_) {
      LuaGuard* g = slot.guard.load(std::memory_order_acquire);
      if (!g) continue;
      std::string stuck = WatchGuard(g, now, Interrupted());
      if (stuck.empty()) continue;
      if (stuck_.empty()) stuck_ = stuck;
      // Under the lock, as the states cannot go while their owner's thread is stuck.
      if (on_stuck_) on_stuck_(stuck);
    }
  }
}

}  // namespace essaim
