// host/daemon/studio/studio_preview.cpp: validating a studio design and rendering its atlas.
#include "host/daemon/studio/studio_preview.h"

#include <algorithm>
#include <atomic>
#include <chrono>

#include "geometry/common/thread_pool.h"
#include "rip/image/image_io.h"

namespace tp::host {

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Rows per render call, as render_piece_images renders them (each pixel on its own either way).
constexpr int kBandRows = 16;
constexpr int kRenderThreads = 2;

Error superseded() { return Error{ErrorCode::kCancelled, "preview superseded by a newer design"}; }

bool stopped(const geometry::CancelToken& a, const geometry::CancelToken& b) { return a.cancelled() || b.cancelled(); }

// Every piece rendered straight into its place of the blank atlas's layout (the pixels
// write_textured_garment packs for the same renderer), in bands of rows on two threads; a
// superseded preview stops at the next band.
Result<geometry::ImageRgba8> render_atlas(const StudioGarment& g, const geometry::PieceRenderer& renderer,
                                          const geometry::CancelToken& mine, const geometry::CancelToken& caller) {
  geometry::ImageRgba8 atlas;
  atlas.width_px = g.atlas_width_px;
  atlas.height_px = g.atlas_height_px;
  atlas.pixels.assign(static_cast<size_t>(atlas.width_px) * atlas.height_px, geometry::Rgba8{255, 255, 255, 0});
  struct Band {
    const AtlasIsland* island;
    int y0;
  };
  std::vector<Band> bands;
  for (const AtlasIsland& is : g.atlas_islands) {
    if (is.piece < 0 || is.piece >= renderer.piece_count() || is.x_px < 0 || is.y_px < 0 ||
        is.x_px + is.width_px > atlas.width_px || is.y_px + is.height_px > atlas.height_px)
      return fail(ErrorCode::kPipeline,
                  "preview atlas: piece " + std::to_string(is.piece) + " does not fit the garment's atlas layout");
    // A piece image starts transparent black (render_piece_image's), the rest of the atlas white.
    for (int r = 0; r < is.height_px; ++r) std::fill_n(&atlas.at(is.x_px, is.y_px + r), is.width_px, geometry::Rgba8{});
    for (int y = 0; y < is.height_px; y += kBandRows) bands.push_back({&is, y});
  }
  std::atomic<bool> cancelled{false};
  ThreadPool pool(kRenderThreads);
  pool.parallel_for(static_cast<int>(bands.size()), [&](int i, int) {
    if (cancelled || stopped(mine, caller)) {
      cancelled = true;
      return;
    }
    const Band& b = bands[static_cast<size_t>(i)];
    const AtlasIsland& is = *b.island;
    const int rows = std::min(kBandRows, is.height_px - b.y0);
    const geometry::Affine2 m =
        is.pixel_to_piece_mm.compose(geometry::Affine2::translation({0, static_cast<double>(b.y0)}));
    renderer.render(is.piece, m, is.width_px, rows, &atlas.at(is.x_px, is.y_px + b.y0), atlas.width_px);
  });
  if (cancelled) return fail(superseded());
  return atlas;
}

}  // namespace

Result<StudioPreview> render_studio_preview(StudioGarment& g, const nlohmann::json& design, const PackageLimits& limits,
                                            const geometry::CancelToken& cancel) {
  // Taken before the lock: a preview still running for an older design stops at its next band.
  const geometry::CancelToken mine = g.begin_preview();
  std::lock_guard lock(g.mu);
  if (stopped(mine, cancel)) return fail(superseded());
  StudioPreview out;
  const auto t0 = std::chrono::steady_clock::now();
  // Only the design is the designer's here: the preview keeps the default finishing, so the
  // atlas layout (pieces' cut outlines at the atlas dpi) stays the mesh's.
  auto job = parse_studio_job(g, studio_manifest(g, {{"design", design}}), limits);
  if (!job) return fail(job.error());
  out.parse_ms = ms_since(t0);
  if (stopped(mine, cancel)) return fail(superseded());
  const auto t1 = std::chrono::steady_clock::now();
  auto renderer = make_job_renderer(*job, g.sewn, studio_render_options(g.atlas_dpi), mine, &g.preview_base);
  if (!renderer) return fail(stopped(mine, cancel) ? superseded() : renderer.error());
  out.build_ms = ms_since(t1);
  const auto t2 = std::chrono::steady_clock::now();
  auto atlas = render_atlas(g, **renderer, mine, cancel);
  if (!atlas) return fail(atlas.error());
  out.render_ms = ms_since(t2);
  const auto t3 = std::chrono::steady_clock::now();
  auto png = rip::encode_png(*atlas, rip::PngChannels::kRgbOverWhite, g.atlas_dpi, kStudioPreviewPngLevel,
                             "preview atlas of garment " + g.id);
  if (!png) return fail(ErrorCode::kIo, png.error().message);
  out.png = std::move(*png);
  out.encode_ms = ms_since(t3);
  return out;
}

}  // namespace tp::host
