// geometry/pattern/internal/segment_intersection.cpp: sweep-and-test self-intersection of outlines.
#include "geometry/pattern/internal/segment_intersection.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tp::geometry::internal {
namespace {

/// Relative size under which a cross product counts as zero (collinear), against coordinate scale.
constexpr double kCollinearRel = 1e-12;

int orientation(Vec2 a, Vec2 b, Vec2 c, double eps) {
  double v = cross(b - a, c - a);
  return v > eps ? 1 : (v < -eps ? -1 : 0);
}

bool on_segment(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Whether closed segments ab and cd share a point; `where` gets one such point.
bool segments_touch(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double eps, Vec2& where) {
  int o1 = orientation(a, b, c, eps), o2 = orientation(a, b, d, eps);
  int o3 = orientation(c, d, a, eps), o4 = orientation(c, d, b, eps);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    double t = cross(c - a, d - c) / cross(b - a, d - c);
    where = a + (b - a) * t;
    return true;
  }
  if (o1 == 0 && on_segment(a, b, c)) { where = c; return true; }
  if (o2 == 0 && on_segment(a, b, d)) { where = d; return true; }
  if (o3 == 0 && on_segment(c, d, a)) { where = a; return true; }
  if (o4 == 0 && on_segment(c, d, b)) { where = b; return true; }
  return false;
}

}  // namespace

std::optional<SelfIntersection> find_self_intersection(const std::vector<Vec2>& poly) {
  const int n = static_cast<int>(poly.size());
  if (n < 3) return std::nullopt;
  double scale = 0;
  for (Vec2 p : poly) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  const double eps = kCollinearRel * std::max(scale * scale, 1.0);

  // Neighbours share a vertex; they only intersect if the outline folds straight back.
  for (int i = 0; i < n; ++i) {
    Vec2 a = poly[i], b = poly[(i + 1) % n], c = poly[(i + 2) % n];
    if (orientation(a, b, c, eps) == 0 && dot(b - a, c - b) < 0)
      return SelfIntersection{i, (i + 1) % n, b};
  }
  // Sweep segments by their left end; test only pairs whose x ranges overlap.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto xmin = [&](int i) { return std::min(poly[i].x, poly[(i + 1) % n].x); };
  auto xmax = [&](int i) { return std::max(poly[i].x, poly[(i + 1) % n].x); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return xmin(a) < xmin(b); });
  for (int oi = 0; oi < n; ++oi) {
    int i = order[oi];
    double right = xmax(i);
    for (int oj = oi + 1; oj < n && xmin(order[oj]) <= right; ++oj) {
      int j = order[oj];
      int d = std::abs(i - j);
      if (d == 1 || d == n - 1) continue;
      Vec2 where;
      if (segments_touch(poly[i], poly[(i + 1) % n], poly[j], poly[(j + 1) % n], eps, where))
        return SelfIntersection{std::min(i, j), std::max(i, j), where};
    }
  }
  return std::nullopt;
}

}  // namespace tp::geometry::internal
