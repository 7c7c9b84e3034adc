// host/pipeline/run_job.cpp: runs a job's stages in order and always leaves report.json behind.
#include "host/pipeline/run_job.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <ctime>

#include "host/common/atomic_file.h"
#include "host/common/text.h"
#include "host/pipeline/internal/order_run.h"
#include "host/pipeline/internal/peak_rss.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/stage_tracker.h"

namespace tp::host {

namespace fs = std::filesystem;

std::string_view to_string(Stage stage) {
  switch (stage) {
    case Stage::kIntake: return "intake";
    case Stage::kPattern: return "pattern";
    case Stage::kMesh: return "mesh";
    case Stage::kGarment: return "garment";
    case Stage::kDesign: return "design";
    case Stage::kMarker: return "marker";
    case Stage::kPrint: return "print";
    case Stage::kOutputs: return "outputs";
  }
  return "unknown";
}

std::string_view to_string(StageState state) {
  switch (state) {
    case StageState::kFresh: return "fresh";
    case StageState::kRunning: return "running";
    case StageState::kDone: return "done";
    case StageState::kFailed: return "failed";
    case StageState::kCancelled: return "cancelled";
    case StageState::kSkipped: return "skipped";
    case StageState::kReused: return "reused";
  }
  return "unknown";
}

namespace {

std::string utc_now() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

Status write_report(const fs::path& out_dir, const nlohmann::json& report) {
  // Text from job files (a DXF's strings, file names) may not be UTF-8: dump_json never throws on
  // it. The report is replaced atomically so a reader never sees half of one.
  return write_file_atomic(out_dir / "report.json", dump_json(report, 2) + "\n");
}

}  // namespace

Status run_job(const Job& job, const RunOptions& options, const geometry::CancelToken& cancel) {
  std::error_code ec;
  fs::create_directories(options.out_dir, ec);
  if (ec) return fail(ErrorCode::kIo, options.out_dir.string() + ": " + ec.message());

  // docs/report.md; "warnings" collects what a person should look at even when the job is done.
  nlohmann::json report = {{"schema", "tp-report/1"}, {"job", job.name}, {"job_id", options.job_id},
                            {"started", utc_now()}, {"warnings", nlohmann::json::array()}};
  // Progress of the print stage: each acknowledged swath against the stage's estimate.
  RunOptions opts = options;
  if (options.on_progress) {
    opts.on_checkpoint = [&options, &report](std::int64_t swath) {
      if (options.on_checkpoint) options.on_checkpoint(swath);
      const auto est = report.find("estimate");
      const std::int64_t total = est != report.end() && est->is_object() ? est->value("swaths", std::int64_t{0}) : 0;
      const double fraction = total > 0 ? std::min(1.0, static_cast<double>(swath + 1) / static_cast<double>(total)) : 0.0;
      options.on_progress(Stage::kPrint, fraction,
                          "swath " + std::to_string(swath + 1) + (total > 0 ? " of " + std::to_string(total) : ""));
    };
  }
  internal::StageTracker tracker(opts, cancel, report);
  internal::PipelineState ps{job, opts, cancel, report};
  auto t0 = std::chrono::steady_clock::now();
  spdlog::info("job {} '{}': running into {}", options.job_id, job.name, options.out_dir.string());

  using StageFn = Status (*)(internal::PipelineState&);
  const std::pair<Stage, StageFn> stages[] = {
      {Stage::kIntake, internal::stage_intake}, {Stage::kPattern, internal::stage_pattern},
      {Stage::kMesh, internal::stage_mesh},     {Stage::kGarment, internal::stage_garment},
      {Stage::kDesign, internal::stage_design}, {Stage::kMarker, internal::stage_marker},
      {Stage::kPrint, internal::stage_print},   {Stage::kOutputs, internal::stage_outputs}};
  // An order (docs/orders.md) drafts, sews and designs every size and copy, then goes on as one job.
  const std::pair<Stage, StageFn> order_stages[] = {
      {Stage::kIntake, internal::stage_intake},       {Stage::kPattern, internal::stage_order_pattern},
      {Stage::kMesh, internal::stage_order_mesh},     {Stage::kGarment, internal::stage_order_garment},
      {Stage::kDesign, internal::stage_order_design}, {Stage::kMarker, internal::stage_marker},
      {Stage::kPrint, internal::stage_print},         {Stage::kOutputs, internal::stage_outputs}};
  Status result = {};
  if (!options.plan_dir.empty()) {
    auto plan = internal::PlanStore::open(options.plan_dir);
    if (plan) ps.plan = std::move(*plan);
    else result = fail(plan.error().with_context("plan"));
  }
  for (const auto& [stage, fn] : job.order ? order_stages : stages) {
    if (!result) break;
    // The RIP's memory: the resident peak while the print stage runs, against what the job held before.
    const std::optional<double> rss_before = stage == Stage::kPrint ? internal::resident_mib() : std::nullopt;
    const bool peak_reset = rss_before && internal::reset_peak_resident();
    result = tracker.run(stage, [&] {
      ps.stage_reused = false;
      return fn(ps);
    }, &ps.stage_reused);
    if (peak_reset && report.contains("rip") && report["rip"].is_object())
      if (auto peak = internal::peak_resident_mib())
        report["rip"]["memory"] = {{"rss_before_mib", *rss_before},
                                   {"peak_rss_mib", *peak},
                                   {"peak_above_before_mib", std::max(0.0, *peak - *rss_before)}};
  }

  internal::finish_order_report(report);
  report["finished"] = utc_now();
  report["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  report["state"] = result ? "done" : result.error().code == ErrorCode::kCancelled ? "cancelled" : "failed";
  if (!result) report["error"] = result.error().message;
  if (auto st = write_report(options.out_dir, report); !st && result) result = st;
  if (result) spdlog::info("job {} '{}': done in {:.1f} s", options.job_id, job.name, report["wall_s"].get<double>());
  else spdlog::warn("job {} '{}': {}", options.job_id, job.name, result.error().message);
  return result;
}

}  // namespace tp::host
