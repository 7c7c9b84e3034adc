// geometry/design/render_piece_image.cpp: renders a piece's bounding box band by band.
#include "geometry/design/render_piece_image.h"

#include <algorithm>
#include <cmath>

#include "geometry/common/thread_pool.h"

namespace tp::geometry {

namespace {

// The piece's blank image and its pixel map (empty for an empty outline or a bad dpi).
PieceImage blank_piece_image(const PieceRenderer& renderer, int piece, double dpi, int margin_px) {
  PieceImage out;
  const Box2 box = bounds(renderer.cut_outline_mm(piece));
  if (box.empty() || !(dpi > 0)) return out;
  const double mm_per_px = 25.4 / dpi;
  const int w = static_cast<int>(std::ceil(box.width() / mm_per_px)) + 2 * margin_px;
  const int h = static_cast<int>(std::ceil(box.height() / mm_per_px)) + 2 * margin_px;
  out.image.width_px = w;
  out.image.height_px = h;
  out.image.pixels.assign(static_cast<size_t>(w) * h, Rgba8{});
  // x right, y down in pixels; the piece's top-left corner (minus the margin) at pixel (0, 0).
  out.pixel_to_piece_mm = {mm_per_px, 0, box.min.x - margin_px * mm_per_px, 0, -mm_per_px, box.max.y + margin_px * mm_per_px};
  return out;
}

}  // namespace

std::vector<PieceImage> render_piece_images(const PieceRenderer& renderer, const std::vector<int>& pieces, double dpi,
                                            int threads) {
  constexpr int kRows = 16;
  std::vector<PieceImage> out;
  std::vector<std::pair<size_t, int>> bands;  // (image, first row)
  for (int piece : pieces) {
    out.push_back(blank_piece_image(renderer, piece, dpi, 2));
    for (int y = 0; y < out.back().image.height_px; y += kRows) bands.emplace_back(out.size() - 1, y);
  }
  auto run = [&](int i, int) {
    const auto [k, y0] = bands[static_cast<size_t>(i)];
    PieceImage& img = out[k];
    const int w = img.image.width_px, rows = std::min(kRows, img.image.height_px - y0);
    const Affine2 m = img.pixel_to_piece_mm.compose(Affine2::translation({0, static_cast<double>(y0)}));
    renderer.render(pieces[k], m, w, rows, img.image.pixels.data() + static_cast<size_t>(y0) * w, w);
  };
  if (threads <= 1) {
    for (int i = 0; i < static_cast<int>(bands.size()); ++i) run(i, 0);
  } else {
    ThreadPool pool(threads);
    pool.parallel_for(static_cast<int>(bands.size()), run);
  }
  return out;
}

PieceImage render_piece_image(const PieceRenderer& renderer, int piece, double dpi, int margin_px, int rows_per_call) {
  PieceImage out = blank_piece_image(renderer, piece, dpi, margin_px);
  const int w = out.image.width_px, h = out.image.height_px;
  if (w <= 0 || h <= 0) return out;
  const int band = rows_per_call > 0 ? rows_per_call : h;
  for (int y0 = 0; y0 < h; y0 += band) {
    const int rows = std::min(band, h - y0);
    const Affine2 m = out.pixel_to_piece_mm.compose(Affine2::translation({0, static_cast<double>(y0)}));
    renderer.render(piece, m, w, rows, out.image.pixels.data() + static_cast<size_t>(y0) * w, w);
  }
  return out;
}

}  // namespace tp::geometry
