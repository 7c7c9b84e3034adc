// geometry/common/thread_pool.h: a fixed pool of worker threads running index-parallel loops, for
// geometry and the layers above it (rip, host).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace tp {

/// `threads` workers (the calling thread counts as worker 0) that run parallel_for loops. Work is
/// handed out by index, so which worker runs an index never affects results that are written by
/// index.
class ThreadPool {
 public:
  /// `threads` <= 0 means std::thread::hardware_concurrency(). `spin_us` > 0: idle workers, and
  /// the caller waiting for a loop to finish, poll for that long before they sleep, for callers
  /// that run many short loops in a row (waking a sleeping thread costs about 60 us on the 2-core
  /// build machine, a virtual one).
  explicit ThreadPool(int threads, int spin_us = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return static_cast<int>(workers_.size()) + 1; }

  /// Runs fn(index, worker) for every index in [0, count) and returns when all have finished.
  /// The caller runs indices too; workers that come after every index is taken skip the loop, so
  /// a loop never waits for a worker the scheduler has not run. `fn` must not throw. Not reentrant.
  void parallel_for(int count, const std::function<void(int index, int worker)>& fn);

 private:
  void worker_loop(int worker);
  void run_indices(int worker);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int, int)>* task_ = nullptr;
  int count_ = 0;
  std::atomic<int> next_{0};
  std::atomic<int> busy_{0};
  std::atomic<std::uint64_t> generation_{0};
  bool stop_ = false;
  bool open_ = false;  ///< the current loop still takes workers (guarded by mutex_)
  int spin_us_ = 0;
};

}  // namespace tp
