// host/pipeline/internal/budget_ticker.cpp: the timer thread behind a stage's time-budget progress.
#include "host/pipeline/internal/budget_ticker.h"

#include <algorithm>
#include <cstdio>

namespace tp::host::internal {

BudgetTicker::BudgetTicker(Callback callback, Stage stage, double budget_s, std::chrono::milliseconds period)
    : callback_(std::move(callback)), stage_(stage), budget_s_(budget_s), period_(period) {
  if (callback_ && budget_s_ > 0) thread_ = std::thread([this] { loop(); });
}

BudgetTicker::~BudgetTicker() {
  {
    std::lock_guard lock(mu_);
    stop_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void BudgetTicker::loop() {
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_lock lock(mu_);
  while (!cv_.wait_for(lock, period_, [this] { return stop_; })) {
    const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double fraction = std::min(0.99, elapsed_s / budget_s_);
    char detail[64];
    std::snprintf(detail, sizeof detail, "%.1f s of %.1f s budget", std::min(elapsed_s, budget_s_), budget_s_);
    lock.unlock();
    callback_(stage_, fraction, detail);
    lock.lock();
  }
}

}  // namespace tp::host::internal
