// host/pipeline/job_garment.cpp: the garment and design stages of run_job, run on their own.
#include "host/pipeline/job_garment.h"

#include "host/pipeline/internal/pipeline_state.h"

namespace tp::host {

Result<JobGarment> sew_job_garment(const Job& job, const std::filesystem::path& out_dir,
                                   const geometry::CancelToken& cancel) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) return fail(ErrorCode::kIo, out_dir.string() + ": " + ec.message());
  RunOptions options;
  options.out_dir = out_dir;
  // Nothing is printed here, so the printer is not asked who it is (intake's preflight).
  options.printer_override = PrinterChoice::kNone;
  JobGarment out;
  internal::PipelineState ps{job, options, cancel, out.report};
  using StageFn = Status (*)(internal::PipelineState&);
  const std::pair<Stage, StageFn> stages[] = {{Stage::kIntake, internal::stage_intake},
                                              {Stage::kPattern, internal::stage_pattern},
                                              {Stage::kMesh, internal::stage_mesh},
                                              {Stage::kGarment, internal::stage_garment}};
  for (const auto& [stage, fn] : stages) {
    if (cancel.cancelled()) return fail(ErrorCode::kCancelled, "cancelled");
    if (auto st = fn(ps); !st) return fail(st.error().with_context(std::string(to_string(stage)) + " stage"));
  }
  if (!ps.garment) return fail(ErrorCode::kPipeline, "garment stage: no garment was made");
  out.pattern = std::move(ps.pattern);
  out.garment = std::move(*ps.garment);
  out.is_3d = ps.garment_is_3d;
  out.body = ps.body;
  return out;
}

Result<std::unique_ptr<geometry::PieceRenderer>> make_job_renderer(
    const Job& job, const JobGarment& garment, const geometry::RenderOptions& options,
    const geometry::CancelToken& cancel, std::shared_ptr<const geometry::RendererBase>* base) {
  RunOptions run;
  nlohmann::json report;
  internal::PipelineState ps{job, run, cancel, report};
  ps.pattern = garment.pattern;
  ps.garment = garment.garment;
  ps.garment_is_3d = garment.is_3d;
  ps.body = garment.body;
  ps.render_options = options;
  if (base) ps.renderer_base = *base;
  if (auto st = internal::stage_design(ps); !st) return fail(st.error().with_context("design stage"));
  if (base) *base = ps.renderer_base;
  return std::move(ps.renderer);
}

}  // namespace tp::host
