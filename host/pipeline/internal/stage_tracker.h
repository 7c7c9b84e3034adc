// host/pipeline/internal/stage_tracker.h: runs pipeline stages in order, timing each, reporting
// its state to the caller (the daemon's store) and into the job report.
#pragma once

#include <chrono>
#include <nlohmann/json.hpp>

#include "host/pipeline/run_job.h"

namespace tp::host::internal {

class StageTracker {
 public:
  StageTracker(const RunOptions& options, const geometry::CancelToken& cancel, nlohmann::json& report)
      : options_(options), cancel_(cancel), report_(report) {
    report_["stages"] = nlohmann::json::array();
    for (Stage s : kAllStages)
      report_["stages"].push_back({{"stage", to_string(s)}, {"state", to_string(StageState::kFresh)}, {"wall_s", nullptr}});
  }

  /// Runs `body` (returning Status) as stage `s`; a cancelled token fails the stage as cancelled.
  /// A stage that succeeds with `*reused` set is recorded as reused (loaded from the plan).
  template <class Body>
  [[nodiscard]] Status run(Stage s, Body&& body, const bool* reused = nullptr) {
    if (cancel_.cancelled()) return finish(s, StageState::kCancelled, 0, fail(ErrorCode::kCancelled, "job cancelled"));
    set(s, StageState::kRunning, 0);
    auto t0 = std::chrono::steady_clock::now();
    Status st = body();
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (st) return finish(s, reused && *reused ? StageState::kReused : StageState::kDone, secs, st);
    bool cancelled = st.error().code == ErrorCode::kCancelled || cancel_.cancelled();
    Error e = st.error();
    if (cancelled) e.code = ErrorCode::kCancelled;
    return finish(s, cancelled ? StageState::kCancelled : StageState::kFailed, secs,
                  fail(e.with_context(std::string(to_string(s)))));
  }

  /// Marks a stage as not applicable to this job.
  void skip(Stage s) { set(s, StageState::kSkipped, 0); }

 private:
  [[nodiscard]] Status finish(Stage s, StageState state, double secs, Status st) {
    set(s, state, secs);
    return st;
  }
  void set(Stage s, StageState state, double secs) {
    for (auto& e : report_["stages"]) {
      if (e["stage"] == to_string(s)) {
        e["state"] = to_string(state);
        // Wall time once the stage has run; null while it has not (fresh, running, skipped).
        const bool ran = state != StageState::kFresh && state != StageState::kRunning && state != StageState::kSkipped;
        e["wall_s"] = ran ? nlohmann::json(secs) : nlohmann::json(nullptr);
      }
    }
    if (options_.on_stage) options_.on_stage(s, state, secs);
  }

  const RunOptions& options_;
  const geometry::CancelToken& cancel_;
  nlohmann::json& report_;
};

}  // namespace tp::host::internal
