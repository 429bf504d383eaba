// The thread pool's two loops: every item exactly once, in contiguous ranges; the balanced
// one lets a free thread take over the work a busy one has not started.
#include "sim/thread_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace essaim {
namespace {

struct Visits {
  std::mutex mutex;
  std::vector<int> count;
  std::vector<std::thread::id> by;
  int ranges = 0;
  explicit Visits(int n) : count(n, 0), by(n) {}
  int Visited() {
    std::lock_guard<std::mutex> lock(mutex);
    return static_cast<int>(std::count_if(count.begin(), count.end(), [](int c) { return c > 0; }));
  }
  void Range(int b, int e) {
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_LE(b, e);
    ++ranges;
    for (int i = b; i < e; ++i) {
      ++count[i];
      by[i] = std::this_thread::get_id();
    }
  }
};

TEST(ThreadPool, EveryItemOnceAtAnyThreadCountAndSize) {
  for (int threads : {1, 2, 3, 8})
    for (int n : {0, 1, 2, 7, 64, 1000}) {
      ThreadPool pool(threads);
      for (bool balanced : {false, true}) {
        Visits v(n);
        auto f = [&](int b, int e) { v.Range(b, e); };
        for (int rep = 0; rep < 3; ++rep) {  // the pool is reused loop after loop
          if (balanced)
            pool.ParallelForBalanced(n, f);
          else
            pool.ParallelFor(n, f);
        }
        for (int i = 0; i < n; ++i) ASSERT_EQ(v.count[i], 3) << "threads " << threads << " n " << n << " item " << i;
        if (!balanced && n > 0) EXPECT_LE(v.ranges, 3 * threads);  // one contiguous chunk per thread
      }
    }
}

TEST(ThreadPool, StaticAndBalancedLoopsInterleaveManyTimes) {
  // A balanced loop returns without waiting for workers still asleep; one that wakes late
  // must neither run items of a loop that has ended nor take those of the next one.
  for (int threads : {2, 4}) {
    ThreadPool pool(threads);
    std::vector<int> count(300, 0);
    int expected = 0;
    auto f = [&](int b, int e) {
      for (int i = b; i < e; ++i) ++count[i];  // items are disjoint: no lock needed
    };
    for (int rep = 0; rep < 2000; ++rep) {
      const int n = (rep * 37) % 300;
      if (rep % 3 == 0)
        pool.ParallelFor(n, f);
      else
        pool.ParallelForBalanced(n, f);
      if (n > 0) ++expected;  // item 0 is in every non-empty loop
    }
    int total = 0;
    for (int rep = 0; rep < 2000; ++rep) total += (rep * 37) % 300;
    int sum = 0;
    for (int c : count) sum += c;
    EXPECT_EQ(count[0], expected);
    EXPECT_EQ(sum, total);
  }
}

TEST(ThreadPool, BalancedRangesShrinkAsTheLoopEnds) {
  ThreadPool pool(2);
  std::vector<std::pair<int, int>> ranges;
  std::mutex m;
  auto f = [&](int b, int e) {
    std::lock_guard<std::mutex> lock(m);
    ranges.emplace_back(b, e);
  };
  pool.ParallelForBalanced(1000, f);
  int largest = 0, smallest = 1000;
  for (auto [b, e] : ranges) {
    largest = std::max(largest, e - b);
    smallest = std::min(smallest, e - b);
  }
  EXPECT_EQ(largest, 1000 / 8);  // the first: the remainder over 4 x 2 threads
  EXPECT_EQ(smallest, 1);        // the last ones: single items
  EXPECT_LT(ranges.size(), 100u);
}

TEST(ThreadPool, BalancedLoopDoesNotWaitForASlowRange) {
  // The range of item 0 is slow: it waits until every other item is done (a fixed sleep
  // was a time a busy machine could miss). With equal static chunks its thread would also
  // have items 1..99 to run, and would wait for the guard; balanced, the other thread takes them.
  ThreadPool pool(2);
  const int n = 200;
  Visits v(n);
  auto f = [&](int b, int e) {
    if (b == 0) {
      const auto guard = std::chrono::steady_clock::now() + std::chrono::seconds(60);  // a hang guard
      while (v.Visited() < n - e && std::chrono::steady_clock::now() < guard)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    v.Range(b, e);
  };
  pool.ParallelForBalanced(n, f);
  int slow_thread_items = 0;
  for (int i = 0; i < n; ++i) slow_thread_items += v.by[i] == v.by[0];
  EXPECT_LE(slow_thread_items, n / 4);  // its first range (n / 8) and little else
}

}  // namespace
}  // namespace essaim
