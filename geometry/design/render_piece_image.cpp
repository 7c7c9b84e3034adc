// geometry/design/render_piece_image.cpp: renders a piece's bounding box band by band.
#include "geometry/design/render_piece_image.h"

#include <algorithm>
#include <cmath>

namespace tp::geometry {

PieceImage render_piece_image(const PieceRenderer& renderer, int piece, double dpi, int margin_px, int rows_per_call) {
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
  const int band = rows_per_call > 0 ? rows_per_call : h;
  for (int y0 = 0; y0 < h; y0 += band) {
    const int rows = std::min(band, h - y0);
    const Affine2 m = out.pixel_to_piece_mm.compose(Affine2::translation({0, static_cast<double>(y0)}));
    renderer.render(piece, m, w, rows, out.image.pixels.data() + static_cast<size_t>(y0) * w, w);
  }
  return out;
}

}  // namespace tp::geometry
