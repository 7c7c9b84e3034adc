// host/bench/bench_marker.h: the RIP benchmark's jobs (panels covering the roll, the nested skirt,
// stand-in rectangles) and a replay source that isolates the pipeline after rendering.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/common/image.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/nesting/marker.h"
#include "host/bench/textured_piece_renderer.h"
#include "rip/common/error.h"
#include "rip/render/band_source.h"

namespace tp::rip {

/// A procedural design (smooth colour fields with fine stripes, photographic in its statistics),
/// `size_px` square, tileable.
geometry::ImageHandle bench_design_texture(int size_px = 1024);

/// A benchmark job: the renderer of some pieces and one block of them nested across the roll; a
/// roll of any length repeats the block (repeat_block).
struct BenchJob {
  std::shared_ptr<const void> keep_alive;  ///< the garment behind a design renderer
  std::unique_ptr<geometry::PieceRenderer> renderer;
  geometry::Marker block;
  std::string description;                 ///< which renderer and design, for the report
};

/// The stand-in: 400 x 500 mm rectangles tiling the width (full coverage), textured with the
/// design at 150 dpi (upsampled 4x at 600 dpi, as a design image usually is).
BenchJob make_textured_bench_job(double width_mm);

/// The real thing: the sample eight-gore skirt (size M) with the paper's cylindrical marbling
/// projected around the body, rendered through the garment correspondence with textured seam
/// allowance; one garment's pieces nested on the roll width by the marker stage's own items and
/// options (host/pipeline/marker_nesting.h) for a job's marker of grain both ways, 2 mm gaps and
/// 5 s of search. Fails with the geometry layer's error.
[[nodiscard]] Result<BenchJob> make_garment_bench_job(double width_mm, int threads);

/// Full coverage through the real design renderer: four panels sewn side by side (a flat job, no
/// body), each cut a quarter of the roll width, carrying a planar projection repeated over the
/// cloth and a planar motif at 60 % opacity, with textured 10 mm allowance across the seams and
/// mirrored at the edges; placed edge to edge. Fails with the geometry layer's error.
[[nodiscard]] Result<BenchJob> make_panel_bench_job(double width_mm, int threads);

/// `block` repeated down a marker `length_mm` long; the last copy is cut by the marker's end.
geometry::Marker repeat_block(const geometry::Marker& block, double length_mm);

/// Render tiles of another source rendered once and replayed cyclically down a roll of `height_px`:
/// `cached_tiles` tiles taken at even steps over its first `sample_rows` rows, so replayed rows
/// keep the marker's mix of blank fabric and design. "Rendering" becomes one copy per pixel.
class ReplaySource final : public BandSource {
 public:
  ReplaySource(const BandSource& inner, int cached_tiles, std::int64_t sample_rows, std::int64_t height_px);
  int width_px() const override { return width_; }
  std::int64_t height_px() const override { return height_; }
  void render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const override;

 private:
  int width_, tiles_;
  std::int64_t height_;
  std::vector<geometry::Rgba8> rows_;  ///< tiles_ * kRenderTileRows rows
};

}  // namespace tp::rip
