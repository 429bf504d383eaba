// A fixed pool of worker threads running one parallel loop at a time. Each robot's sense
// and control write only its own state, so results do not depend on the thread count or
// on which thread ran which robot.
#pragma once
#include <atomic>
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
  /// Runs f(begin, end) over [0, n) split into Size() contiguous chunks (ARGoS's
  /// balance_quantity); the calling thread takes the first chunk. Returns when all chunks
  /// are done. Takes the callable by reference through a plain function pointer: nothing
  /// is allocated per call.
  template <class F>
  void ParallelFor(int n, F& f) {
    Run(
        n, /*balanced=*/false, [](void* c, int b, int e) { (*static_cast<F*>(c))(b, e); }, &f);
  }
  /// The same, but [0, n) is handed out in contiguous ranges, in order, to whichever thread
  /// is free (OpenMP's "guided" schedule: each range is the remainder over 4 × Size(), at
  /// least one item). Robots cost different amounts (a crowd, a dead robot) and a thread
  /// may lose its core to another process: the others take up the slack instead of
  /// waiting. Returns once every item is done, without waiting for workers that have not
  /// woken up yet (they find nothing left). f may be called any number of times per
  /// thread, never for the same item twice.
  template <class F>
  void ParallelForBalanced(int n, F& f) {
    Run(
        n, /*balanced=*/true, [](void* c, int b, int e) { (*static_cast<F*>(c))(b, e); }, &f);
  }

 private:
  using Job = void (*)(void*, int, int);
  void Run(int n, bool balanced, Job job, void* ctx);
  /// One thread's share of loop `generation`: its static chunk, or ranges until none is left.
  void Work(int thread, long generation, Job job, void* ctx, int n, bool balanced);
  void WorkerLoop(int worker);
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_cv_, done_cv_;
  Job job_ = nullptr;
  void* ctx_ = nullptr;
  int n_ = 0;
  bool balanced_ = false;
  // Balanced loops: the loop's generation (high 32 bits) and the first item not yet handed
  // out (low 32), claimed together so that a worker waking after its loop has ended can
  // never take items of the next one; and the count of items finished.
  std::atomic<unsigned long long> claim_{0};
  std::atomic<int> done_items_{0};
  long generation_ = 0;
  int pending_ = 0;  // static loops: workers still running their chunk
  bool stop_ = false;
};

}  // namespace essaim
