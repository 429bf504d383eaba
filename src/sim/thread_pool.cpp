#include "sim/thread_pool.h"

#include <algorithm>

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
}  // namespace

void ThreadPool::Work(int thread, Job job, void* ctx, int n, bool balanced) {
  if (!balanced) {
    int b, e;
    Chunk(n, Size(), thread, &b, &e);
    job(ctx, b, e);
    return;
  }
  const int divisor = 4 * Size();
  int b = next_.load(std::memory_order_relaxed);
  for (;;) {
    if (b >= n) return;
    const int size = std::max(1, (n - b) / divisor);
    // On failure b is reloaded with the current value and the range recomputed.
    if (!next_.compare_exchange_weak(b, b + size, std::memory_order_relaxed)) continue;
    job(ctx, b, b + size);
    b = next_.load(std::memory_order_relaxed);
  }
}

void ThreadPool::Run(int n, bool balanced, Job job, void* ctx) {
  if (workers_.empty()) {
    job(ctx, 0, n);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = job;
    ctx_ = ctx;
    n_ = n;
    balanced_ = balanced;
    next_.store(0, std::memory_order_relaxed);  // published to the workers by the mutex
    pending_ = static_cast<int>(workers_.size());
    ++generation_;
  }
  start_cv_.notify_all();
  Work(0, job, ctx, n, balanced);
  std::unique_lock<std::mutex> lock(mutex_);
  done_cv_.wait(lock, [this] { return pending_ == 0; });
  job_ = nullptr;
}

void ThreadPool::WorkerLoop(int worker) {
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
    Work(worker, job, ctx, n, balanced);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--pending_ == 0) done_cv_.notify_one();
    }
  }
}

}  // namespace essaim
