// host/daemon/studio/studio_preview.cpp: validating a studio design and rendering its atlas.
#include "host/daemon/studio/studio_preview.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "host/pipeline/garment_files.h"

namespace tp::host {

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Result<StudioPreview> render_studio_preview(StudioGarment& g, const nlohmann::json& design, const PackageLimits& limits,
                                            const geometry::CancelToken& cancel) {
  std::lock_guard lock(g.mu);
  StudioPreview out;
  const auto t0 = std::chrono::steady_clock::now();
  // Only the design is the designer's here: the preview keeps the default finishing, so the
  // atlas layout (pieces' cut outlines at the atlas dpi) stays the mesh's.
  auto job = parse_studio_job(g, studio_manifest(g, {{"design", design}}), limits);
  if (!job) return fail(job.error());
  auto renderer = make_job_renderer(*job, g.sewn, studio_render_options(g.atlas_dpi), cancel, &g.preview_base);
  if (!renderer) return fail(renderer.error());
  out.build_ms = ms_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  const std::filesystem::path dir = g.dir / "preview";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fail(ErrorCode::kIo, dir.string() + ": " + ec.message());
  auto files = write_textured_garment(dir, "atlas", g.sewn.pattern, g.sewn.garment, **renderer, g.atlas_dpi);
  if (!files) return fail(files.error());
  if (files->texture_width_px != g.atlas_width_px || files->texture_height_px != g.atlas_height_px)
    return fail(ErrorCode::kPipeline, "preview atlas is " + std::to_string(files->texture_width_px) + "x" +
                                          std::to_string(files->texture_height_px) + " px, the garment's mesh maps " +
                                          std::to_string(g.atlas_width_px) + "x" + std::to_string(g.atlas_height_px));
  std::ifstream in(dir / files->texture, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) return fail(ErrorCode::kIo, (dir / files->texture).string() + ": cannot read");
  out.png = bytes.str();
  out.render_ms = ms_since(t1);
  return out;
}

}  // namespace tp::host
