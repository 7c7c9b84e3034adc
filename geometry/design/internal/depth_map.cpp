// geometry/design/internal/depth_map.cpp: rasterises the garment into the projection's z-buffer.
#include "geometry/design/internal/depth_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/common/tolerances.h"

namespace tp::geometry::internal {
namespace {

// The map has at most this many cells on a side.
constexpr int kMaxCells = 2048;
constexpr float kEmpty = -std::numeric_limits<float>::infinity();
// Around a non-repeating image the map reaches this far past its edge (cells and mm): the
// per-pixel filter reads one cell beyond a point's own, triangle classification one more.
constexpr int kImageReachCells = 4;
constexpr double kImageReachMm = 2.0;

}  // namespace

DepthMap::DepthMap(const PlanarField& field, const GarmentSurface& surface, double tolerance_mm, double min_cell_mm)
    : tolerance_mm_(tolerance_mm) {
  const auto& V = surface.garment().vertices_mm;
  std::vector<Vec3> pc(V.size());
  Box2 box;
  for (size_t i = 0; i < V.size(); ++i) {
    pc[i] = field.plane_coordinates(V[i]);
    box.add({pc[i].x, pc[i].y});
  }
  if (box.empty()) return;
  cell_mm_ = std::max(min_cell_mm, std::max(box.width(), box.height()) / (kMaxCells - 4));
  origin_ = box.min - Vec2{2 * cell_mm_, 2 * cell_mm_};
  nx_ = static_cast<int>(std::ceil(box.width() / cell_mm_)) + 5;
  ny_ = static_cast<int>(std::ceil(box.height() / cell_mm_)) + 5;
  // Only the cells under the image (and the filter's reach around it) are ever read for a
  // non-repeating image: the map keeps the garment-wide cell size but covers just those cells.
  if (const Box2 image = field.image_box_mm(); !image.empty()) {
    const double reach_mm = kImageReachCells * cell_mm_ + kImageReachMm;
    const int ix0 = std::max(0, static_cast<int>(std::floor((image.min.x - reach_mm - origin_.x) / cell_mm_)));
    const int iy0 = std::max(0, static_cast<int>(std::floor((image.min.y - reach_mm - origin_.y) / cell_mm_)));
    const int ix1 = std::min(nx_, static_cast<int>(std::ceil((image.max.x + reach_mm - origin_.x) / cell_mm_)) + 1);
    const int iy1 = std::min(ny_, static_cast<int>(std::ceil((image.max.y + reach_mm - origin_.y) / cell_mm_)) + 1);
    origin_ = origin_ + Vec2{ix0 * cell_mm_, iy0 * cell_mm_};
    nx_ = std::max(0, ix1 - ix0);
    ny_ = std::max(0, iy1 - iy0);
    if (nx_ == 0 || ny_ == 0) {
      nx_ = ny_ = 0;
      return;
    }
  }
  depth_.assign(static_cast<size_t>(nx_) * ny_, kEmpty);
  auto splat = [&](int ix, int iy, double d) {
    if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) return;
    float& z = depth_[static_cast<size_t>(iy) * nx_ + ix];
    z = std::max(z, static_cast<float>(d));
  };
  for (const auto& t : surface.triangles_3d()) {
    const Vec3 a = pc[static_cast<size_t>(t[0])], b = pc[static_cast<size_t>(t[1])], c = pc[static_cast<size_t>(t[2])];
    // Corners always land, so triangles smaller than a cell still occlude.
    for (Vec3 p : {a, b, c})
      splat(static_cast<int>(std::floor((p.x - origin_.x) / cell_mm_)), static_cast<int>(std::floor((p.y - origin_.y) / cell_mm_)), p.z);
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (std::abs(det) < kParallelDeterminant) continue;
    const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
    const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
    const int ix0 = static_cast<int>(std::floor((x0 - origin_.x) / cell_mm_)), ix1 = static_cast<int>(std::floor((x1 - origin_.x) / cell_mm_));
    const int iy0 = static_cast<int>(std::floor((y0 - origin_.y) / cell_mm_)), iy1 = static_cast<int>(std::floor((y1 - origin_.y) / cell_mm_));
    for (int iy = iy0; iy <= iy1; ++iy) {
      for (int ix = ix0; ix <= ix1; ++ix) {
        const double px = origin_.x + (ix + 0.5) * cell_mm_, py = origin_.y + (iy + 0.5) * cell_mm_;
        const double wb = ((px - a.x) * (c.y - a.y) - (c.x - a.x) * (py - a.y)) / det;
        const double wc = ((b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y)) / det;
        const double wa = 1 - wb - wc;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        splat(ix, iy, wa * a.z + wb * b.z + wc * c.z);
      }
    }
  }
}

double DepthMap::front(int ix, int iy) const {
  if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) return kEmpty;
  return depth_[static_cast<size_t>(iy) * nx_ + ix];
}

double DepthMap::visibility(Vec3 p) const {
  if (nx_ == 0) return 1;
  const double fx = (p.x - origin_.x) / cell_mm_ - 0.5, fy = (p.y - origin_.y) / cell_mm_ - 0.5;
  const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
  const double tx = fx - ix, ty = fy - iy;
  // A neighbouring cell's surface tilted away from the image may sit deeper by up to a cell's
  // width times its slope; the tolerance covers the garment's own thickness and that.
  auto lit = [&](int x, int y) { return p.z >= front(x, y) - tolerance_mm_ ? 1.0 : 0.0; };
  return (1 - ty) * ((1 - tx) * lit(ix, iy) + tx * lit(ix + 1, iy)) + ty * ((1 - tx) * lit(ix, iy + 1) + tx * lit(ix + 1, iy + 1));
}

DepthMap::Coverage DepthMap::classify(const std::array<Vec3, 3>& t) const {
  if (nx_ == 0) return Coverage::kVisible;
  const Vec3 a = t[0], b = t[1], c = t[2];
  const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
  const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
  // One cell of margin: the per-pixel filter reads the neighbours of the cell a point is in.
  const int ix0 = static_cast<int>(std::floor((x0 - origin_.x) / cell_mm_)) - 1, ix1 = static_cast<int>(std::floor((x1 - origin_.x) / cell_mm_)) + 1;
  const int iy0 = static_cast<int>(std::floor((y0 - origin_.y) / cell_mm_)) - 1, iy1 = static_cast<int>(std::floor((y1 - origin_.y) / cell_mm_)) + 1;
  bool any_lit = false, any_dark = false;
  for (int iy = iy0; iy <= iy1; ++iy) {
    for (int ix = ix0; ix <= ix1; ++ix) {
      const double px = origin_.x + (ix + 0.5) * cell_mm_, py = origin_.y + (iy + 0.5) * cell_mm_;
      double z;
      if (std::abs(det) < kParallelDeterminant) {
        z = std::min({a.z, b.z, c.z});
      } else {
        // The triangle's plane extended over the margin cells (conservative near its edges).
        const double wb = ((px - a.x) * (c.y - a.y) - (c.x - a.x) * (py - a.y)) / det;
        const double wc = ((b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y)) / det;
        const double wa = 1 - wb - wc;
        z = wa * a.z + wb * b.z + wc * c.z;
        z = std::min(z, std::max({a.z, b.z, c.z}));
        z = std::max(z, std::min({a.z, b.z, c.z}));
      }
      if (z >= front(ix, iy) - tolerance_mm_) any_lit = true;
      else any_dark = true;
    }
  }
  if (!any_dark) return Coverage::kVisible;
  if (!any_lit) return Coverage::kHidden;
  return Coverage::kPartial;
}

}  // namespace tp::geometry::internal
