// geometry/common/thread_pool.cpp: the worker pool (threads made once, reused across loops).
#include "geometry/common/thread_pool.h"

#include <algorithm>
#include <chrono>
#include <system_error>

namespace tp {
namespace {

// Polls `ready` for up to `spin_us` microseconds; true once it held.
template <class Ready>
bool spin_until(int spin_us, Ready&& ready) {
  if (spin_us <= 0) return false;
  const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(spin_us);
  for (int k = 0;; ++k) {
    if (ready()) return true;
    if ((k & 63) == 63 && std::chrono::steady_clock::now() > until) return false;
  }
}

}  // namespace

ThreadPool::ThreadPool(int threads, int spin_us) : spin_us_(spin_us) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // A system out of threads (EAGAIN) leaves the pool with the workers it has: the caller's
  // thread does the rest, and results do not depend on the split.
  try {
    for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { worker_loop(w); });
  } catch (const std::system_error&) {
  }
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void ThreadPool::run_indices(int worker) {
  for (int i = next_.fetch_add(1, std::memory_order_relaxed); i < count_;
       i = next_.fetch_add(1, std::memory_order_relaxed))
    (*task_)(i, worker);
}

void ThreadPool::worker_loop(int worker) {
  std::uint64_t seen = 0;
  for (;;) {
    // A new loop bumps the generation under the lock, after its task is set.
    spin_until(spin_us_, [&] { return generation_.load(std::memory_order_acquire) != seen; });
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_.load(std::memory_order_relaxed) != seen; });
      if (stop_) return;
      seen = generation_.load(std::memory_order_relaxed);
      // The caller closes a loop once every index is taken: a worker that comes later (it was
      // not scheduled in time) skips it, so the caller never waits for one that did nothing.
      if (!open_) continue;
      busy_.fetch_add(1, std::memory_order_relaxed);
    }
    run_indices(worker);
    {
      std::lock_guard lock(mutex_);
      if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) done_.notify_one();
    }
  }
}

void ThreadPool::parallel_for(int count, const std::function<void(int, int)>& fn) {
  if (count <= 0) return;
  if (workers_.empty() || count == 1) {
    for (int i = 0; i < count; ++i) fn(i, 0);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    task_ = &fn;
    count_ = count;
    next_.store(0, std::memory_order_relaxed);
    busy_.store(0, std::memory_order_relaxed);
    open_ = true;
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  run_indices(0);
  // Every index is taken: close the loop to workers not yet in it, then wait for those in it.
  // Waiting for every worker instead made a loop last a scheduler time slice whenever a worker
  // was not running (two drape tests side by side on 2 cores: 36 s each, 1.3 s alone).
  {
    std::lock_guard lock(mutex_);
    open_ = false;
  }
  spin_until(spin_us_, [&] { return busy_.load(std::memory_order_acquire) == 0; });
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return busy_.load(std::memory_order_relaxed) == 0; });
  task_ = nullptr;
}

}  // namespace tp
