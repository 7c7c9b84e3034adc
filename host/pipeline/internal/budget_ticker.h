// host/pipeline/internal/budget_ticker.h: reports a stage's progress as elapsed time over its
// time budget from a timer thread, for stages whose algorithm has no progress hook (nesting).
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "host/pipeline/run_job.h"

namespace tp::host::internal {

class BudgetTicker {
 public:
  using Callback = std::function<void(Stage, double fraction, const std::string& detail)>;
  /// Starts reporting `stage` every `period` until destroyed; fractions stay below 1 (the stage's
  /// own "done" says 1).
  BudgetTicker(Callback callback, Stage stage, double budget_s,
               std::chrono::milliseconds period = std::chrono::milliseconds(250));
  ~BudgetTicker();
  BudgetTicker(const BudgetTicker&) = delete;
  BudgetTicker& operator=(const BudgetTicker&) = delete;

 private:
  void loop();

  Callback callback_;
  Stage stage_;
  double budget_s_;
  std::chrono::milliseconds period_;
  std::mutex mu_;
  std::condition_variable cv_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace tp::host::internal
