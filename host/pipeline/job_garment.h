// host/pipeline/job_garment.h: the pipeline's own pattern, mesh, garment and design stages run
// apart from a print, for tools that sew a job's garment once and render many designs on it
// (the design studio's previews).
#pragma once

#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "geometry/body/body_sdf.h"
#include "geometry/common/cancel.h"
#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"
#include "host/common/error.h"
#include "host/job/job.h"

namespace tp::host {

/// A job's garment as the pipeline's garment stage made it.
struct JobGarment {
  geometry::Pattern pattern;
  geometry::Garment garment;                      ///< the correspondence the design is made on
  bool is_3d = false;                             ///< false: laid flat (a job without a body)
  std::shared_ptr<const geometry::BodySdf> body;  ///< null for a flat garment
  nlohmann::json report;                          ///< the stages' report sections (garment, sewing, ...)
};

/// Runs the intake, pattern, mesh and garment stages of `job` (its design is not read), writing
/// the garment stage's files (garment.obj, previews) into `out_dir` (created). Fails with the
/// stage's error (a pattern that cannot be read, a garment that fails its fit checks) or
/// kCancelled.
[[nodiscard]] Result<JobGarment> sew_job_garment(const Job& job, const std::filesystem::path& out_dir,
                                                 const geometry::CancelToken& cancel);

/// Runs the design stage of `job` (its layers and finishing) on `garment`, sewn from the same
/// garment section: the renderer the print stage would use, built to `options` (a preview at a
/// low dpi needs a coarser tolerance than print). Fails naming the layer or field.
/// `base`, when given, carries the design-independent part between calls: used when it holds one
/// (made by an earlier call with this garment, the same finishing and options), filled when empty.
[[nodiscard]] Result<std::unique_ptr<geometry::PieceRenderer>> make_job_renderer(
    const Job& job, const JobGarment& garment, const geometry::RenderOptions& options,
    const geometry::CancelToken& cancel, std::shared_ptr<const geometry::RendererBase>* base = nullptr);

}  // namespace tp::host
