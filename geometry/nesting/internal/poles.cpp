// geometry/nesting/internal/poles.cpp: pole generation by a best-first quadtree search in the
// manner of polylabel, extended to keep clear of poles already taken.
#include "geometry/nesting/internal/poles.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>

namespace tp::geometry::nesting {
namespace {

// A square cell of the search and its clearance: signed distance from its centre to the nearest
// obstacle (outline edge or taken pole), negative outside the free region.
struct Cell {
  Vec2 c;
  double half = 0;
  double clearance = 0;
  double potential() const { return clearance + half * 1.4142135623730951; }
};

double clearance(const Polygon& poly, const std::vector<Circle>& taken, Vec2 p) {
  double d = distance_to_boundary(poly, p);
  if (!point_in_polygon(poly, p)) return -d;
  for (const Circle& t : taken) d = std::min(d, norm(p - t.c) - t.r);
  return d;
}

// Cap on cells examined per circle: bounds the cost on long thin or very detailed outlines.
constexpr int kMaxCellsPerCircle = 40000;

}  // namespace

double distance_to_boundary(const Polygon& poly, Vec2 p) {
  double best = 1e300;
  for (size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % n], ab = b - a;
    const double len2 = dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, norm(p - (a + ab * t)));
  }
  return best;
}

Circle largest_free_circle(const Polygon& ccw, const std::vector<Circle>& taken, double precision_mm) {
  const Box2 box = bounds(ccw);
  const double side = std::max(box.width(), box.height());
  if (!(side > 0)) return {};
  auto cmp = [](const Cell& a, const Cell& b) { return a.potential() < b.potential(); };
  std::priority_queue<Cell, std::vector<Cell>, decltype(cmp)> queue(cmp);
  // Seed with a grid of square cells covering the bounding box.
  const double cell = std::min(box.width(), box.height()) > 0 ? std::min(box.width(), box.height()) : side;
  const double half = cell / 2;
  for (double x = box.min.x; x < box.max.x; x += cell)
    for (double y = box.min.y; y < box.max.y; y += cell) {
      Vec2 c{x + half, y + half};
      queue.push({c, half, clearance(ccw, taken, c)});
    }
  Cell best{{}, 0, 0};
  {
    // The area centroid is often the answer for compact outlines: a good first bound.
    double a = 0, cx = 0, cy = 0;
    for (size_t i = 0, n = ccw.size(); i < n; ++i) {
      const Vec2 p = ccw[i], q = ccw[(i + 1) % n];
      const double f = cross(p, q);
      a += f;
      cx += (p.x + q.x) * f;
      cy += (p.y + q.y) * f;
    }
    if (a != 0) {
      Vec2 c{cx / (3 * a), cy / (3 * a)};
      best = {c, 0, clearance(ccw, taken, c)};
    }
  }
  int examined = 0;
  while (!queue.empty() && examined < kMaxCellsPerCircle) {
    const Cell c = queue.top();
    queue.pop();
    ++examined;
    if (c.clearance > best.clearance) best = c;
    if (c.potential() - best.clearance <= precision_mm) continue;
    const double h = c.half / 2;
    for (int dx = -1; dx <= 1; dx += 2)
      for (int dy = -1; dy <= 1; dy += 2) {
        Vec2 p{c.c.x + dx * h, c.c.y + dy * h};
        queue.push({p, h, clearance(ccw, taken, p)});
      }
  }
  if (best.clearance <= 0) return {};
  return {best.c, best.clearance};
}

std::vector<Circle> compute_poles(const Polygon& ccw, const PoleLimits& limits) {
  std::vector<Circle> poles;
  const double area = std::fabs(signed_area(ccw));
  const Box2 box = bounds(ccw);
  const double precision = 1e-3 * std::hypot(box.width(), box.height());
  double covered = 0;
  while (static_cast<int>(poles.size()) < limits.max_poles) {
    const Circle c = largest_free_circle(ccw, poles, precision);
    if (!(c.r > precision)) break;
    poles.push_back(c);
    covered += std::numbers::pi * c.r * c.r;
    const double coverage = area > 0 ? covered / area : 1.0;
    bool enough = false;
    for (int k = 0; k < 2; ++k)
      enough |= coverage > limits.coverage[k] && static_cast<int>(poles.size()) >= limits.enough_at[k];
    if (enough) break;
  }
  if (poles.empty()) {
    // A sliver too thin for the precision still needs one circle to be quantified by.
    const Circle c = largest_free_circle(ccw, {}, 0.0);
    poles.push_back(c.r > 0 ? c : Circle{ccw[0], 0.0});
  }
  return poles;
}

}  // namespace tp::geometry::nesting
