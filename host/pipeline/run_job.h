// host/pipeline/run_job.h: the whole pipeline for one validated job, from pattern to printed
// fabric, with explicit stages (STYLE.md: an enum of stages with per-job state).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "geometry/common/cancel.h"
#include "host/common/error.h"
#include "host/job/job.h"
#include "host/pipeline/printer_live.h"

namespace tp::host {

/// Pipeline stages in the order they run.
enum class Stage { kIntake, kPattern, kMesh, kGarment, kDesign, kMarker, kPrint, kOutputs };
inline constexpr Stage kAllStages[] = {Stage::kIntake, Stage::kPattern, Stage::kMesh,  Stage::kGarment,
                                       Stage::kDesign, Stage::kMarker,  Stage::kPrint, Stage::kOutputs};
std::string_view to_string(Stage stage);

/// kReused: the stage's result was loaded from the job's stored plan (its inputs are unchanged).
enum class StageState { kFresh, kRunning, kDone, kFailed, kCancelled, kSkipped, kReused };
std::string_view to_string(StageState state);

/// How to run a job (where outputs go, which printer, where to resume).
struct RunOptions {
  std::filesystem::path out_dir;
  /// Printer to use instead of the job's own print.printer (kNone: everything but printing).
  std::optional<PrinterChoice> printer_override;
  /// Swaths with index <= this were acknowledged by the printer in an earlier attempt.
  std::int64_t resume_after_swath = -1;
  /// The job's plan directory (garment, pieces, marker, swath plan; docs/plan-storage.md). Empty:
  /// nothing is stored and every stage runs. A step whose inputs are unchanged is loaded from it.
  std::filesystem::path plan_dir;
  /// Non-zero id for logs and the printer's job-begin message (printers use 0 for "no job").
  std::int64_t job_id = 0;
  std::function<void(Stage, StageState, double seconds)> on_stage;
  std::function<void(std::int64_t swath)> on_checkpoint;
  /// Progress within a stage, where the stage can tell: `fraction` 0..1 of its work done and a
  /// short `detail` ("swath 12 of 40"). Called on the pipeline's thread, or (the marker stage's
  /// time-budget ticks) on a timer thread while the pipeline thread waits: never two at once.
  std::function<void(Stage, double fraction, const std::string& detail)> on_progress;
  /// The live printer while the print stage runs: each status report and each fired cue. Called on
  /// the pipeline's thread; keep it quick.
  std::function<void(const PrinterLive&)> on_printer;
  /// Test hook, not a job option (docs/colour.md, `printctl run --debug-misplace`): after nesting,
  /// print this piece moved by (dx, dy) mm and turned by `rotation_deg` about the centre of its cut
  /// outline, while the cut file and the measures keep its planned place, as a misfed or misplaced
  /// print would be. The printed-seam figures must see it; the contone ones cannot.
  struct Misplacement {
    std::string piece;
    double dx_mm = 0, dy_mm = 0, rotation_deg = 0;
  };
  std::optional<Misplacement> misplace_for_test;
};

/// Runs every stage of `job`. Always writes `<out_dir>/report.json` (stages, timings, figures,
/// and the error if one stage failed); fails with that stage's error, or kCancelled.
[[nodiscard]] Status run_job(const Job& job, const RunOptions& options, const geometry::CancelToken& cancel);

}  // namespace tp::host
