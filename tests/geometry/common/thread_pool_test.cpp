// tests/geometry/common/thread_pool_test.cpp: the shared worker pool runs every index once, on a worker in range.
#include "geometry/common/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace tp {
namespace {

TEST(ThreadPool, EveryIndexRunsOnceOnAWorkerInRange) {
  for (int threads : {1, 2, 4}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.size(), threads);
    for (int round = 0; round < 20; ++round) {
      const int n = 1 + round * 37;
      std::vector<std::atomic<int>> runs(static_cast<size_t>(n));
      std::atomic<bool> worker_out_of_range{false};
      pool.parallel_for(n, [&](int i, int worker) {
        runs[static_cast<size_t>(i)].fetch_add(1);
        if (worker < 0 || worker >= threads) worker_out_of_range = true;
      });
      for (int i = 0; i < n; ++i)
        ASSERT_EQ(runs[static_cast<size_t>(i)].load(), 1) << "threads " << threads << " index " << i;
      EXPECT_FALSE(worker_out_of_range);
    }
  }
}

TEST(ThreadPool, ResultsWrittenByIndexDoNotDependOnTheThreadCount) {
  auto sums = [](int threads) {
    ThreadPool pool(threads);
    std::vector<double> out(1000);
    pool.parallel_for(1000, [&](int i, int) { out[static_cast<size_t>(i)] = 1.0 / (i + 1); });
    return out;
  };
  EXPECT_EQ(sums(1), sums(3));
}

TEST(ThreadPool, PollingWorkersRunManyShortLoopsEveryIndexOnce) {
  ThreadPool pool(2, 300);
  std::vector<std::atomic<int>> runs(8);
  for (int loop = 0; loop < 5000; ++loop) pool.parallel_for(8, [&](int i, int) { runs[static_cast<size_t>(i)]++; });
  for (auto& r : runs) EXPECT_EQ(r.load(), 5000);
}

// More workers than the machine has cores, loops shorter than a wake-up: the caller takes most
// indices itself and closes each loop before some workers come, which then skip it. Every index
// still runs once, none runs in a later loop, and no loop waits forever.
TEST(ThreadPool, WorkersThatComeAfterALoopClosedSkipItAndEveryIndexRunsOnce) {
  for (int spin_us : {0, 300}) {
    ThreadPool pool(6, spin_us);
    std::vector<std::atomic<int>> runs(3);
    std::atomic<int> wrong_loop{0};
    for (int loop = 0; loop < 20000; ++loop)
      pool.parallel_for(3, [&](int i, int) {
        if (runs[static_cast<size_t>(i)].fetch_add(1) != loop) wrong_loop++;
      });
    for (auto& r : runs) EXPECT_EQ(r.load(), 20000) << "spin " << spin_us;
    EXPECT_EQ(wrong_loop.load(), 0) << "spin " << spin_us;
  }
}

TEST(ThreadPool, EmptyLoopReturnsAtOnce) {
  ThreadPool pool(2);
  int calls = 0;
  pool.parallel_for(0, [&](int, int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace tp
