// A fixed pool of worker threads running one parallel loop at a time. Work is split in
// contiguous robot ranges (ARGoS's balance_quantity): each robot's sense and control
// write only its own state, so results do not depend on the thread count.
#pragma once
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace essaim {

class ThreadPool {
 public:
  explicit ThreadPool(int threads);
  ~ThreadPool();
  int Size() const { return static_cast<int>(workers_.size()) + 1; }
  /// Runs f(begin, end) over [0, n) split into Size() contiguous chunks; the calling
  /// thread takes the first chunk. Returns when all chunks are done. Takes the callable
  /// by reference through a plain function pointer: nothing is allocated per call.
  template <class F>
  void ParallelFor(int n, F& f) {
    Run(n, [](void* c, int b, int e) { (*static_cast<F*>(c))(b, e); }, &f);
  }

 private:
  using Job = void (*)(void*, int, int);
  void Run(int n, Job job, void* ctx);
  void WorkerLoop(int worker);
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_cv_, done_cv_;
  Job job_ = nullptr;
  void* ctx_ = nullptr;
  int n_ = 0;
  long generation_ = 0;
  int pending_ = 0;
  bool stop_ = false;
};

}  // namespace essaim
