// geometry/nesting/internal/overlap.h: the collision kernels of the search: polygon-polygon
// collision (touching counts) and the pole-based overlap measure used as its loss.
#pragma once

#include <vector>

#include "geometry/common/vec.h"
#include "geometry/nesting/internal/poles.h"

namespace tp::geometry::nesting {

/// Smaller / larger of two numbers (std::fmin/fmax handle NaNs through a library call, which
/// costs a fifth of the search time here).
[[nodiscard]] inline double lo(double a, double b) { return b < a ? b : a; }
[[nodiscard]] inline double hi(double a, double b) { return a < b ? b : a; }

/// Poles as float arrays padded to a multiple of 4 (far away, radius 0), for the SIMD proxy.
struct PoleSoA {
  std::vector<float> x, y, r;
  void assign(const std::vector<Circle>& poles);
};

/// True when boxes a and b share at least one point.
[[nodiscard]] inline bool boxes_touch(const Box2& a, const Box2& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

/// True when box `inner` lies within box `outer` (boundaries may touch).
[[nodiscard]] inline bool box_within(const Box2& inner, const Box2& outer) {
  return inner.min.x >= outer.min.x && inner.max.x <= outer.max.x && inner.min.y >= outer.min.y &&
         inner.max.y <= outer.max.y;
}

/// Polygon view for the kernels: vertices, box and a point strictly inside.
struct PolyRef {
  const Vec2* pts = nullptr;
  int n = 0;
  Box2 box;
  Vec2 inner;
};

/// True when two simple polygons collide: their boundaries cross or touch, or one contains the
/// other. Conservative for touching shapes (the clearance added to every outline keeps touching
/// collision outlines legal). `ea` and `eb` are scratch buffers.
[[nodiscard]] bool polygons_collide(const PolyRef& a, const PolyRef& b, std::vector<int>& ea, std::vector<int>& eb);

/// Overlap proxy between two sets of poles (those of `b` shifted by `shift_b`): the sum over pole
/// pairs of their penetration depth times the smaller radius, with a smooth positive tail of
/// width `eps` for pairs that do not penetrate. Units mm². Single precision: it ranks
/// placements, it does not decide collisions. Every term is positive, so the sum stops (and is
/// returned, above `limit`) as soon as it passes `limit`.
[[nodiscard]] double overlap_proxy(const PoleSoA& a, const std::vector<Circle>& b, Vec2 shift_b, double eps,
                                   double limit = 1e300);

}  // namespace tp::geometry::nesting
