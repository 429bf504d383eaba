#include "sim/thread_pool.h"

#include <algorithm>
#include <cstdint>

#include "core/alt_stack.h"

namespace essaim {

ThreadPool::ThreadPool(int threads) {
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { WorkerLoop(i); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_cv_.notify_all();
  for (std::thread& t : workers_) t.join();
}

namespace {
void Chunk(int n, int parts, int k, int* begin, int* end) {
  int base = n / parts, extra = n % parts;
  *begin = k * base + (k < extra ? k : extra);
  *end = *begin + base + (k < extra ? 1 : 0);
}

using Claim = unsigned long long;
Claim Pack(long generation, int next) {
  return (static_cast<Claim>(static_cast<uint32_t>(generation)) << 32) | static_cast<uint32_t>(next);
}
}  // namespace

void ThreadPool::Work(int thread, long generation, Job job, void* ctx, int n, bool balanced) {
  if (!balanced) {
    int b, e;
    Chunk(n, Size(), thread, &b, &e);
    job(ctx, b, e);
    return;
  }
  const int divisor = 4 * Size();
  const Claim tag = Pack(generation, 0);
  Claim c = claim_.load(std::memory_order_relaxed);
  for (;;) {
    if ((c & ~Claim{0xffffffffu}) != tag) return;  // a later loop: this one is over
    const int b = static_cast<int>(c & 0xffffffffu);
    if (b >= n) return;
    const int size = std::max(1, (n - b) / divisor);
    // On failure c is reloaded with the current value and the range recomputed.
    if (!claim_.compare_exchange_weak(c, c + static_cast<Claim>(size), std::memory_order_relaxed)) continue;
    job(ctx, b, b + size);
    // Release: the range's writes are visible to the thread that sees the count complete.
    if (done_items_.fetch_add(size, std::memory_order_acq_rel) + size == n) {
      std::lock_guard<std::mutex> lock(mutex_);
      done_cv_.notify_one();
    }
    c = claim_.load(std::memory_order_relaxed);
  }
}

void ThreadPool::Run(int n, bool balanced, Job job, void* ctx) {
  if (workers_.empty()) {
    job(ctx, 0, n);
    return;
  }
  long generation;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = job;
    ctx_ = ctx;
    n_ = n;
    balanced_ = balanced;
    generation = ++generation_;
    claim_.store(Pack(generation, 0), std::memory_order_relaxed);  // published by the mutex
    done_items_.store(0, std::memory_order_relaxed);
    pending_ = balanced ? 0 : static_cast<int>(workers_.size());
  }
  start_cv_.notify_all();
  Work(0, generation, job, ctx, n, balanced);
  std::unique_lock<std::mutex> lock(mutex_);
  if (balanced)
    done_cv_.wait(lock, [&] { return done_items_.load(std::memory_order_acquire) == n; });
  else
    done_cv_.wait(lock, [this] { return pending_ == 0; });
  job_ = nullptr;
}

void ThreadPool::WorkerLoop(int worker) {
  UseAlternateSignalStack();  // controllers run here: a crash handler must run after an overflow
  long seen = 0;
  for (;;) {
    Job job;
    void* ctx;
    int n;
    bool balanced;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_cv_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
      ctx = ctx_;
      n = n_;
      balanced = balanced_;
    }
    Work(worker, seen, job, ctx, n, balanced);
    if (balanced) continue;  // the caller counts finished items, not workers
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--pending_ == 0) done_cv_.notify_one();
    }
  }
}

}  // namespace essaim
