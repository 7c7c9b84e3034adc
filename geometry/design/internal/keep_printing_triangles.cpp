// geometry/design/internal/keep_printing_triangles.cpp: marks a coarse grid of the cells that
// print, grows it by the margin and keeps the triangles that touch it.
#include "geometry/design/internal/keep_printing_triangles.h"

#include <algorithm>
#include <cmath>

#include "geometry/design/internal/render_builder.h"

namespace tp::geometry::internal {
namespace {

// Texels of filter footprint around an image's edge that may still pick up its colour (a coarse
// preview pixel over a 10 px/mm text image with 8 anisotropic taps).
constexpr double kFootprintTexels = 64;

// Whether entry `e` of triangle `t` can print anything.
bool entry_prints(const RenderTri& t, const TriLayer& e, const std::vector<LayerRuntime>& layers) {
  const LayerRuntime& L = layers[e.layer];
  if (L.kind == LayerRuntime::Kind::kStroke) return e.count > 0;
  if (!L.texture || !L.texture->image) return true;
  const MipImage& im = *L.texture->image;
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (const Vec2& p : t.p) {
    u0 = std::min(u0, e.u.at(p)), u1 = std::max(u1, e.u.at(p));
    v0 = std::min(v0, e.v.at(p)), v1 = std::max(v1, e.v.at(p));
  }
  const bool u_hits = im.wrap_u() == Wrap::kRepeat || (u1 >= -kFootprintTexels && u0 <= im.width() + kFootprintTexels);
  const bool v_hits = im.wrap_v() == Wrap::kRepeat || (v1 >= -kFootprintTexels && v0 <= im.height() + kFootprintTexels);
  return u_hits && v_hits;
}

Box2 tri_box(const RenderTri& t) {
  Box2 b;
  for (const Vec2& p : t.p) b.add(p);
  return b;
}

}  // namespace

std::size_t keep_printing_triangles(PieceData& piece, const std::vector<LayerRuntime>& layers, double margin_mm) {
  // The printing region: boxes of printing triangles and of marks, grown by the margin.
  std::vector<Box2> hot;
  Box2 all;
  for (size_t t = 0; t < piece.tris.size(); ++t) {
    const Box2 b = tri_box(piece.tris[t]);
    all.add(b.min), all.add(b.max);
    for (std::uint32_t k = piece.layer_start[t]; k < piece.layer_start[t + 1]; ++k) {
      if (!entry_prints(piece.tris[t], piece.layers[k], layers)) continue;
      hot.push_back(b);
      break;
    }
  }
  for (const MarkSegment& m : piece.marks) {
    Box2 b;
    b.add(m.a), b.add(m.b);
    b.min = b.min - Vec2{m.half_width_mm, m.half_width_mm};
    b.max = b.max + Vec2{m.half_width_mm, m.half_width_mm};
    hot.push_back(b);
  }
  PieceData out;
  out.cut_outline = std::move(piece.cut_outline);
  out.marks = std::move(piece.marks);
  out.mark_colour = piece.mark_colour;
  out.stroke_segments = std::move(piece.stroke_segments);
  out.layer_start.assign(1, 0);
  if (!hot.empty() && !all.empty()) {
    // A grid of cells of the margin's size: a cell is hot when a grown box touches it.
    const double cell = std::max(margin_mm, 0.5);
    const Vec2 o = all.min - Vec2{2 * cell, 2 * cell};
    const int nx = static_cast<int>(std::ceil(all.width() / cell)) + 5;
    const int ny = static_cast<int>(std::ceil(all.height() / cell)) + 5;
    std::vector<std::uint8_t> grid(static_cast<size_t>(nx) * static_cast<size_t>(ny), 0);
    auto cells = [&](const Box2& b, double grow, int& x0, int& x1, int& y0, int& y1) {
      x0 = std::clamp(static_cast<int>(std::floor((b.min.x - grow - o.x) / cell)), 0, nx - 1);
      x1 = std::clamp(static_cast<int>(std::floor((b.max.x + grow - o.x) / cell)), 0, nx - 1);
      y0 = std::clamp(static_cast<int>(std::floor((b.min.y - grow - o.y) / cell)), 0, ny - 1);
      y1 = std::clamp(static_cast<int>(std::floor((b.max.y + grow - o.y) / cell)), 0, ny - 1);
    };
    for (const Box2& b : hot) {
      int x0, x1, y0, y1;
      cells(b, margin_mm, x0, x1, y0, y1);
      for (int y = y0; y <= y1; ++y)
        std::fill(grid.begin() + y * nx + x0, grid.begin() + y * nx + x1 + 1, std::uint8_t{1});
    }
    for (size_t t = 0; t < piece.tris.size(); ++t) {
      int x0, x1, y0, y1;
      cells(tri_box(piece.tris[t]), 0, x0, x1, y0, y1);
      bool keep = false;
      for (int y = y0; y <= y1 && !keep; ++y)
        for (int x = x0; x <= x1 && !keep; ++x) keep = grid[static_cast<size_t>(y) * nx + x] != 0;
      if (!keep) continue;
      out.tris.push_back(piece.tris[t]);
      out.layers.insert(out.layers.end(), piece.layers.begin() + piece.layer_start[t],
                        piece.layers.begin() + piece.layer_start[t + 1]);
      out.layer_start.push_back(static_cast<std::uint32_t>(out.layers.size()));
    }
  }
  out.tris.shrink_to_fit();
  out.layers.shrink_to_fit();
  build_grid(out);
  piece = std::move(out);
  return piece.tris.size();
}

}  // namespace tp::geometry::internal
