// host/pipeline/internal/plan_steps.h: the stored plan as the stages use it: inputs hashes per
// step, loading a step from the plan when its inputs are unchanged, saving it when it is made.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "device/model/printer_model.h"
#include "device/swath/swath.h"
#include "geometry/nesting/nest_pieces.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/plan_codec.h"

namespace tp::host::internal {

/// Inputs of the pattern, mesh and garment stages: the job's `garment` section and the bytes of
/// the files it names (pattern, garment mesh, body mesh).
[[nodiscard]] Result<std::string> garment_inputs_hash(const Job& job);

/// Sets ps.garment_key; when the plan holds a garment made from these inputs, remembers its file
/// so the mesh stage can be skipped and returns true.
[[nodiscard]] Result<bool> find_plan_garment(PipelineState& ps);

/// The stored garment (find_plan_garment said there is one) into ps.garment, checked against
/// the pattern, and the stitch gaps measured when it was sewn into `stitch_gaps_mm` (one list per
/// stitch, mm). Fails naming the file when it is corrupt or belongs to another pattern.
[[nodiscard]] Status load_plan_garment(PipelineState& ps, std::vector<std::vector<double>>* stitch_gaps_mm);

/// Records ps.garment and its stitch gaps (mm, per stitch) in the plan under ps.garment_key
/// (no-op without a plan). Called once the garment has passed its fit checks.
[[nodiscard]] Status save_plan_garment(PipelineState& ps, const std::vector<std::vector<double>>& stitch_gaps_mm);

/// The stored markers when the plan holds markers nested from exactly `items` under `options`.
[[nodiscard]] Result<std::optional<std::vector<geometry::Marker>>> find_plan_markers(
    PipelineState& ps, const std::vector<geometry::NestItem>& items, const geometry::NestOptions& options);

/// Records the nested pieces and markers (no-op without a plan).
[[nodiscard]] Status save_plan_markers(PipelineState& ps, const std::vector<geometry::NestItem>& items,
                                       const geometry::NestOptions& options,
                                       const std::vector<geometry::Marker>& markers, const geometry::NestStats& stats);

/// The swath plan of a print: checks every swath the RIP makes against the stored plan (same
/// inputs), or records them when there is none, and saves a complete new plan at the end.
class SwathPlan {
 public:
  /// Looks the plan up for the print's inputs (the garment, the markers, the job's design,
  /// finishing and print sections, their asset files and the printer model).
  [[nodiscard]] static Result<SwathPlan> open(PipelineState& ps, const device::PrinterModel& model,
                                              std::uint32_t first_swath);
  /// Fails (kPipeline) when `swath` differs from the stored plan: the print would not continue
  /// the fabric already printed.
  [[nodiscard]] Status check(const device::Swath& swath);
  /// After the RIP: saves a new plan (only a complete one, from swath 0) and reports what was done.
  [[nodiscard]] Status finish(std::uint32_t swaths_total);

 private:
  PipelineState* ps_ = nullptr;
  std::string key_;
  std::uint32_t first_ = 0;
  std::optional<std::vector<PlannedSwath>> stored_;
  std::vector<PlannedSwath> made_;
  std::uint32_t verified_ = 0;
};

}  // namespace tp::host::internal
