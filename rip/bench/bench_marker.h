// rip/bench/bench_marker.h: the RIP benchmark's job: a roll fully covered by textured pieces, and a
// replay source that isolates the pipeline after rendering.
#pragma once

#include <memory>
#include <vector>

#include "geometry/common/image.h"
#include "geometry/nesting/marker.h"
#include "rip/render/band_source.h"
#include "rip/render/textured_piece_renderer.h"

namespace tp::rip {

/// A procedural design (smooth colour fields with fine stripes, photographic in its statistics),
/// `size_px` square, tileable.
geometry::ImageHandle bench_design_texture(int size_px = 1024);

/// A full-coverage marker: `width_mm` x `length_mm` tiled with 400 x 500 mm pieces textured with the
/// design at 150 dpi (upsampled 4x at 600 dpi, as a design image usually is).
struct BenchMarker {
  std::unique_ptr<TexturedPieceRenderer> renderer;
  geometry::Marker marker;
};
BenchMarker make_bench_marker(double width_mm, double length_mm);

/// Rows of another source rendered once (the first `cached_rows`), replayed cyclically down a roll of
/// `height_px`: the cost of "rendering" becomes one copy per pixel.
class ReplaySource final : public BandSource {
 public:
  ReplaySource(const BandSource& inner, int cached_rows, std::int64_t height_px);
  int width_px() const override { return width_; }
  std::int64_t height_px() const override { return height_; }
  void render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const override;

 private:
  int width_, cached_rows_;
  std::int64_t height_;
  std::vector<geometry::Rgba8> rows_;
};

}  // namespace tp::rip
