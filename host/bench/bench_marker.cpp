// host/bench/bench_marker.cpp: the benchmark's jobs (stand-in rectangles, the nested sample skirt
// with its projected design) and the replay source.
#include "host/bench/bench_marker.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include <spdlog/fmt/fmt.h>

#include "geometry/allowance/finishing.h"
#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/sample_designs.h"
#include "geometry/garment/flat_garment.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/nesting/nest_pieces.h"
#include "geometry/pattern/curve.h"
#include "geometry/samples/garments.h"
#include "host/pipeline/marker_nesting.h"

namespace tp::rip {

namespace {
constexpr double kPieceWidthMm = 400, kPieceLengthMm = 500;
constexpr double kDesignDpi = 150;
}  // namespace

geometry::ImageHandle bench_design_texture(int size_px) {
  auto img = std::make_shared<geometry::ImageRgba8>();
  img->width_px = img->height_px = size_px;
  img->source = "bench design";
  img->pixels.resize(static_cast<size_t>(size_px) * size_px);
  // Sums of sines with whole periods across the tile, so it repeats without a seam.
  const double k = 2 * std::numbers::pi / size_px;
  for (int y = 0; y < size_px; ++y)
    for (int x = 0; x < size_px; ++x) {
      const double a = std::sin(3 * k * x + 2 * std::sin(2 * k * y)), b = std::cos(5 * k * y + std::sin(4 * k * x));
      const double stripes = 0.5 + 0.5 * std::sin(k * 64 * (x + y));
      auto ch = [](double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
      img->pixels[static_cast<size_t>(y) * size_px + x] = {ch(0.5 + 0.45 * a), ch(0.5 + 0.4 * b * stripes),
                                                           ch(0.45 + 0.35 * a * b + 0.15 * stripes), 255};
    }
  return img;
}

BenchJob make_textured_bench_job(double width_mm) {
  BenchJob job;
  auto texture = bench_design_texture();
  const geometry::Polygon rect{{0, 0}, {kPieceWidthMm, 0}, {kPieceWidthMm, kPieceLengthMm}, {0, kPieceLengthMm}};
  std::vector<TexturedPieceRenderer::Piece> pieces{{rect, texture, kDesignDpi / 25.4, {}}};
  job.block.width_mm = width_mm;
  job.block.length_mm = kPieceLengthMm;
  for (double x = 0; x < width_mm; x += kPieceWidthMm) job.block.placements.push_back({0, 0, false, {x, 0}});
  job.block.utilisation = 1.0;
  job.renderer = std::make_unique<TexturedPieceRenderer>(std::move(pieces));
  job.description = "textured-rectangles (stand-in renderer, full coverage)";
  return job;
}

Result<BenchJob> make_garment_bench_job(double width_mm, int threads) {
  auto sample = geometry::samples::make_garment("skirt8", "M");
  if (!sample) return fail(ErrorCode::kGeometry, "bench garment skirt8: " + sample.error().what());
  auto garment = std::make_shared<geometry::samples::SampleGarment>(std::move(*sample));
  const geometry::Design design = geometry::sample_design("skirt8", garment->garment);
  geometry::Finishing finishing;
  finishing.marks = geometry::MarkMode::kNone;
  geometry::RenderOptions options;
  options.build_threads = std::max(1, threads);
  auto renderer = geometry::make_piece_renderer(garment->pattern, garment->garment, design, finishing, options);
  if (!renderer) return fail(ErrorCode::kGeometry, "bench garment skirt8: " + renderer.error().what());

  // One garment nested across the roll as the marker stage nests a job's: the job fields of the
  // bench (grain both ways, no mirror, 2 mm gaps, no selvedge margin, 5 s of search).
  host::MarkerSpec marker;
  marker.fabric_width_mm = width_mm;
  marker.gap_mm = 2;
  marker.edge_margin_mm = 0;
  marker.rotations = "grain";
  marker.mirror = false;
  marker.time_limit_s = 5;
  marker.iterations = 0;
  const std::vector<geometry::NestItem> items = host::marker_nest_items(garment->pattern, **renderer, marker);
  geometry::NestOptions nest = host::marker_nest_options(marker);
  nest.threads = std::max(1, threads);
  auto markers = geometry::nest_pieces(items, nest);
  if (!markers || markers->empty())
    return fail(ErrorCode::kGeometry,
                "bench garment skirt8: nesting failed: " + (markers ? std::string("no marker") : markers.error().what()));
  BenchJob job;
  job.block = markers->front();
  job.description = fmt::format("garment-skirt8 (design renderer: cylindrical marbling, textured allowance; {} pieces "
                                "nested in {:.0f} mm, {:.1f} % used, repeated)",
                                (*renderer)->piece_count(), job.block.length_mm, job.block.utilisation * 100);
  job.renderer = std::move(*renderer);
  job.keep_alive = garment;
  return job;
}

Result<BenchJob> make_panel_bench_job(double width_mm, int threads) {
  // Four panels sewn side by side into one wide cloth, each cut exactly a quarter of the roll
  // width with 10 mm allowance all round, 1 m of seam line long.
  constexpr int kPanels = 4;
  constexpr double kAllowanceMm = 10, kSeamLengthMm = 1000;
  const double cut_w = width_mm / kPanels, w = cut_w - 2 * kAllowanceMm;
  if (w <= 50) return fail(ErrorCode::kInvalidArgument, fmt::format("bench panels: roll {} mm is too narrow", width_mm));
  geometry::Pattern pattern;
  pattern.name = "bench_panels";
  pattern.size = "one";
  using geometry::make_line_edge;
  for (int k = 0; k < kPanels; ++k) {
    geometry::Piece piece;
    piece.name = fmt::format("panel_{}", k + 1);
    piece.edges = {make_line_edge("bottom", {0, 0}, {w, 0}), make_line_edge("side_right", {w, 0}, {w, kSeamLengthMm}),
                   make_line_edge("top", {w, kSeamLengthMm}, {0, kSeamLengthMm}),
                   make_line_edge("side_left", {0, kSeamLengthMm}, {0, 0})};
    piece.grain = geometry::GrainLine{{w / 2, 100}, {w / 2, kSeamLengthMm - 100}};
    pattern.pieces.push_back(std::move(piece));
  }
  for (int k = 0; k + 1 < kPanels; ++k)
    pattern.stitches.push_back({{k, 1, 0, -1}, {k + 1, 3, 0, -1}, false});
  geometry::TriangulateOptions mesh_opt;
  mesh_opt.target_edge_mm = 20;
  auto meshes = geometry::mesh_pattern(pattern, mesh_opt);
  if (!meshes) return fail(ErrorCode::kGeometry, "bench panels: " + meshes.error().what());
  auto garment = geometry::flat_garment(pattern, *meshes);
  if (!garment) return fail(ErrorCode::kGeometry, "bench panels: " + garment.error().what());
  auto keep = std::make_shared<std::pair<geometry::Pattern, geometry::Garment>>(std::move(pattern), std::move(*garment));

  // The design, made in the layout's plane: the bench image projected flat and repeated every
  // 320 mm, and a large planar motif (the same image turned) over the middle panels.
  geometry::Design design;
  geometry::PlanarProjection ground;
  ground.image = bench_design_texture();
  ground.centre_mm = {width_mm / 2, kSeamLengthMm / 2, 0};
  ground.width_mm = 320;
  ground.repeat = true;
  design.layers.push_back({"ground", 1.0, ground});
  geometry::PlanarProjection motif = ground;
  motif.up = {0.5, 0.866, 0};
  motif.width_mm = 700;
  motif.repeat = false;
  design.layers.push_back({"motif", 0.6, motif});

  geometry::Finishing finishing;
  finishing.seam_allowance_mm = finishing.hem_allowance_mm = finishing.edge_allowance_mm = kAllowanceMm;
  finishing.reflect_hem_corners = false;
  finishing.marks = geometry::MarkMode::kNone;
  geometry::RenderOptions options;
  options.build_threads = std::max(1, threads);
  auto renderer = geometry::make_piece_renderer(keep->first, keep->second, design, finishing, options);
  if (!renderer) return fail(ErrorCode::kGeometry, "bench panels: " + renderer.error().what());

  BenchJob job;
  job.block.width_mm = width_mm;
  job.block.length_mm = kSeamLengthMm + 2 * kAllowanceMm;
  for (int k = 0; k < kPanels; ++k)
    job.block.placements.push_back({k, 0, false, {k * cut_w + kAllowanceMm, kAllowanceMm}});
  double cut_area = 0;
  for (int k = 0; k < kPanels; ++k) cut_area += std::abs(geometry::signed_area((*renderer)->cut_outline_mm(k)));
  job.block.utilisation = cut_area / (job.block.width_mm * job.block.length_mm);
  job.description = "panels (design renderer: flat planar projections, textured allowance across seams; 4 panels "
                    "sewn side by side, cut edge to edge: full coverage)";
  job.renderer = std::move(*renderer);
  job.keep_alive = keep;
  return job;
}

geometry::Marker repeat_block(const geometry::Marker& block, double length_mm) {
  geometry::Marker m;
  m.width_mm = block.width_mm;
  m.length_mm = length_mm;
  m.utilisation = block.utilisation;
  for (double y = 0; y < length_mm; y += block.length_mm)
    for (geometry::PiecePlacement pl : block.placements) {
      pl.offset_mm.y += y;
      m.placements.push_back(pl);
    }
  return m;
}

ReplaySource::ReplaySource(const BandSource& inner, int cached_tiles, std::int64_t sample_rows, std::int64_t height_px)
    : width_(inner.width_px()), tiles_(cached_tiles), height_(height_px) {
  rows_.resize(static_cast<size_t>(width_) * tiles_ * kRenderTileRows);
  const std::int64_t span_tiles = std::max<std::int64_t>(1, std::min(sample_rows, inner.height_px()) / kRenderTileRows);
  for (int t = 0; t < tiles_; ++t) {
    const std::int64_t src_tile = t * span_tiles / tiles_;
    inner.render_rows(src_tile * kRenderTileRows, kRenderTileRows,
                      rows_.data() + static_cast<size_t>(t) * kRenderTileRows * width_, width_);
  }
}

void ReplaySource::render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const {
  for (int r = 0; r < rows; ++r) {
    const std::int64_t y = y0 + r;
    const std::int64_t src = (y / kRenderTileRows % tiles_) * kRenderTileRows + y % kRenderTileRows;
    std::memcpy(static_cast<void*>(out + r * stride_px), rows_.data() + src * width_, sizeof(geometry::Rgba8) * static_cast<size_t>(width_));
  }
}

}  // namespace tp::rip
