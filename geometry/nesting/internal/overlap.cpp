// geometry/nesting/internal/overlap.cpp: segment tests, polygon collision and the pole overlap
// proxy. This is the inner loop of the search: no allocation, early exits first.
#include "geometry/nesting/internal/overlap.h"

#include <cmath>

#include "geometry/nesting/internal/poles.h"

namespace tp::geometry::nesting {
namespace {

inline double orient(Vec2 a, Vec2 b, Vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Segments (p1,p2) and (q1,q2) share a point. Their boxes are known to touch, which settles the
// collinear case.
inline bool segments_touch(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
  const double o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
  if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0)) return false;
  const double o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
  if ((o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0)) return false;
  return true;
}

inline bool edge_touches_box(Vec2 a, Vec2 b, const Box2& box) {
  return std::fmin(a.x, b.x) <= box.max.x && std::fmax(a.x, b.x) >= box.min.x && std::fmin(a.y, b.y) <= box.max.y &&
         std::fmax(a.y, b.y) >= box.min.y;
}

bool point_in(const PolyRef& p, Vec2 q) {
  bool inside = false;
  for (int i = 0, j = p.n - 1; i < p.n; j = i++) {
    const Vec2 a = p.pts[i], b = p.pts[j];
    if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

}  // namespace

bool polygons_collide(const PolyRef& a, const PolyRef& b, std::vector<int>& ea, std::vector<int>& eb) {
  // Only edges that reach into the common box can meet.
  Box2 common;
  common.min = {std::fmax(a.box.min.x, b.box.min.x), std::fmax(a.box.min.y, b.box.min.y)};
  common.max = {std::fmin(a.box.max.x, b.box.max.x), std::fmin(a.box.max.y, b.box.max.y)};
  ea.clear();
  eb.clear();
  for (int i = 0; i < a.n; ++i) {
    const int j = i + 1 == a.n ? 0 : i + 1;
    if (edge_touches_box(a.pts[i], a.pts[j], common)) ea.push_back(i);
  }
  if (!ea.empty()) {
    for (int i = 0; i < b.n; ++i) {
      const int j = i + 1 == b.n ? 0 : i + 1;
      if (edge_touches_box(b.pts[i], b.pts[j], common)) eb.push_back(i);
    }
    for (int i : ea) {
      const Vec2 p1 = a.pts[i], p2 = a.pts[i + 1 == a.n ? 0 : i + 1];
      const double xmin = std::fmin(p1.x, p2.x), xmax = std::fmax(p1.x, p2.x);
      const double ymin = std::fmin(p1.y, p2.y), ymax = std::fmax(p1.y, p2.y);
      for (int k : eb) {
        const Vec2 q1 = b.pts[k], q2 = b.pts[k + 1 == b.n ? 0 : k + 1];
        if (std::fmax(q1.x, q2.x) < xmin || std::fmin(q1.x, q2.x) > xmax || std::fmax(q1.y, q2.y) < ymin ||
            std::fmin(q1.y, q2.y) > ymax)
          continue;
        if (segments_touch(p1, p2, q1, q2)) return true;
      }
    }
  }
  // Boundaries apart: they collide only if one contains the other.
  if (box_within(a.box, b.box) && point_in(b, a.inner)) return true;
  if (box_within(b.box, a.box) && point_in(a, b.inner)) return true;
  return false;
}

double overlap_proxy(const std::vector<Circle>& a, const std::vector<Circle>& b, Vec2 shift_b, double eps) {
  double total = 0;
  const double eps2 = eps * eps;
  for (const Circle& p : a) {
    for (const Circle& q : b) {
      const double dx = p.c.x - q.c.x - shift_b.x, dy = p.c.y - q.c.y - shift_b.y;
      const double pd = p.r + q.r - std::sqrt(dx * dx + dy * dy);
      const double depth = pd >= eps ? pd : eps2 / (2.0 * eps - pd);
      total += depth * std::fmin(p.r, q.r);
    }
  }
  return 3.14159265358979323846 * total;
}

}  // namespace tp::geometry::nesting
