// host/pipeline/internal/pipeline_state.h: what the stages of one job hand to each other.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "geometry/allowance/finishing.h"
#include "geometry/body/body_sdf.h"
#include "geometry/body/measurements.h"
#include "geometry/design/design.h"
#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/garment/garment.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/nesting/marker.h"
#include "geometry/pattern/pattern.h"
#include "host/job/job.h"
#include "host/pipeline/internal/plan_store.h"
#include "host/pipeline/run_job.h"

namespace tp::host::internal {

struct PipelineState {
  PipelineState(const Job& j, const RunOptions& o, const geometry::CancelToken& c, nlohmann::json& r)
      : job(j), options(o), cancel(c), report(r) {}

  const Job& job;
  const RunOptions& options;
  const geometry::CancelToken& cancel;
  nlohmann::json& report;

  geometry::Pattern pattern;
  /// Per pattern stitch, where it came from: {"source": "pattern"|"job"|"suggested", "score", "reason"}.
  std::vector<nlohmann::json> stitch_sources;
  std::optional<geometry::BodyMeasurements> measurements;   ///< sample garments and dress forms
  std::shared_ptr<const geometry::BodySdf> body;            ///< collision body, if the job has one
  std::optional<geometry::PatternMesh> meshes;
  std::optional<geometry::Garment> garment;       ///< 3D (or flat) correspondence
  bool garment_is_3d = false;
  geometry::Design design;
  geometry::Finishing finishing;
  std::unique_ptr<geometry::PieceRenderer> renderer;
  /// The renderer's design-independent part: given (the studio's garment session keeps it), the
  /// design stage reuses it; else the stage prepares it from the garment and finishing.
  std::shared_ptr<const geometry::RendererBase> renderer_base;
  geometry::RenderOptions render_options;         ///< the design stage's renderer (defaults: 600 dpi accuracy)
  /// > 0: the design is an overlay (an order copy's text and labels over its size's renderer), so
  /// the renderer keeps only what prints and this margin around it (make_overlay_renderer).
  double overlay_margin_mm = 0;
  std::vector<geometry::Marker> markers;          ///< as nested, each in its own frame
  geometry::Marker roll;                          ///< all markers one after another on the roll
  std::vector<double> marker_start_mm;            ///< where each marker starts on the roll
  /// When this run opened the job on the printer (file clock): printer records written before it
  /// are an earlier run's (printed_fabric_wait.h).
  std::optional<std::filesystem::file_time_type> print_began;

  // The job's stored plan (RunOptions::plan_dir), and what each plan step was made from.
  std::optional<PlanStore> plan;
  std::string garment_key;                        ///< inputs hash of pattern, mesh and garment
  std::optional<std::filesystem::path> plan_garment;  ///< stored garment valid for garment_key
  std::string garment_digest;                     ///< hash of the garment as used (plan file text)
  std::string marker_digest;                      ///< hash of the markers as used (plan file text)
  bool stage_reused = false;                      ///< set by a stage that loaded its result from the plan
  std::shared_ptr<struct OrderRun> order;         ///< an order job's sizes and copies (order_run.h)
};

// One function per stage (stage_<name>.cpp), each filling PipelineState and the report.
[[nodiscard]] Status stage_intake(PipelineState& ps);
[[nodiscard]] Status stage_pattern(PipelineState& ps);
[[nodiscard]] Status stage_mesh(PipelineState& ps);
[[nodiscard]] Status stage_garment(PipelineState& ps);
[[nodiscard]] Status stage_design(PipelineState& ps);
[[nodiscard]] Status stage_marker(PipelineState& ps);
[[nodiscard]] Status stage_print(PipelineState& ps);
[[nodiscard]] Status stage_outputs(PipelineState& ps);

}  // namespace tp::host::internal
