// rip/bench/bench_marker.cpp: the benchmark's design texture, full-coverage marker and replay source.
#include "rip/bench/bench_marker.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tp::rip {

namespace {
constexpr double kPieceWidthMm = 400, kPieceLengthMm = 500;
constexpr double kDesignDpi = 150;
constexpr double kPi = 3.14159265358979323846;
}  // namespace

geometry::ImageHandle bench_design_texture(int size_px) {
  auto img = std::make_shared<geometry::ImageRgba8>();
  img->width_px = img->height_px = size_px;
  img->source = "bench design";
  img->pixels.resize(static_cast<size_t>(size_px) * size_px);
  // Sums of sines with whole periods across the tile, so it repeats without a seam.
  const double k = 2 * kPi / size_px;
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

BenchMarker make_bench_marker(double width_mm, double length_mm) {
  BenchMarker bm;
  auto texture = bench_design_texture();
  const geometry::Polygon rect{{0, 0}, {kPieceWidthMm, 0}, {kPieceWidthMm, kPieceLengthMm}, {0, kPieceLengthMm}};
  std::vector<TexturedPieceRenderer::Piece> pieces{{rect, texture, kDesignDpi / 25.4, {}}};
  bm.marker.width_mm = width_mm;
  bm.marker.length_mm = length_mm;
  for (double y = 0; y < length_mm; y += kPieceLengthMm)
    for (double x = 0; x < width_mm; x += kPieceWidthMm) bm.marker.placements.push_back({0, 0, false, {x, y}});
  bm.marker.utilisation = 1.0;
  bm.renderer = std::make_unique<TexturedPieceRenderer>(std::move(pieces));
  return bm;
}

ReplaySource::ReplaySource(const BandSource& inner, int cached_rows, std::int64_t height_px)
    : width_(inner.width_px()), cached_rows_(cached_rows), height_(height_px) {
  rows_.resize(static_cast<size_t>(width_) * cached_rows_);
  for (int y = 0; y < cached_rows_; y += kRenderTileRows)
    inner.render_rows(y, std::min(kRenderTileRows, cached_rows_ - y), rows_.data() + static_cast<size_t>(y) * width_, width_);
}

void ReplaySource::render_rows(std::int64_t y0, int rows, geometry::Rgba8* out, std::ptrdiff_t stride_px) const {
  for (int r = 0; r < rows; ++r) {
    const std::int64_t src = (y0 + r) % cached_rows_;
    std::memcpy(static_cast<void*>(out + r * stride_px), rows_.data() + src * width_, sizeof(geometry::Rgba8) * static_cast<size_t>(width_));
  }
}

}  // namespace tp::rip
