// geometry/design/fit_cylinder.cpp: minimum enclosing circle of the garment seen along the axis.
#include "geometry/design/fit_cylinder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

/// A point this much (relative to the radius) outside a circle is still in it, so a circle through
/// three points contains them despite rounding.
constexpr double kRadiusSlackRel = 1e-12;

struct Circle {
  Vec2 c;
  double r = -1;
  bool contains(Vec2 p) const { return norm(p - c) <= r * (1 + kRadiusSlackRel) + kBoundarySlack; }
};

Circle from2(Vec2 a, Vec2 b) { return {(a + b) * 0.5, norm(a - b) * 0.5}; }

Circle from3(Vec2 a, Vec2 b, Vec2 c) {
  const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
  if (std::abs(d) < kParallelDeterminant) {
    // Collinear: the widest pair spans the circle.
    Circle best = from2(a, b);
    for (Circle k : {from2(a, c), from2(b, c)})
      if (k.r > best.r) best = k;
    return best;
  }
  const double a2 = dot(a, a), b2 = dot(b, b), c2 = dot(c, c);
  const Vec2 o{(a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
               (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d};
  return {o, norm(a - o)};
}

// Iterative Welzl over a shuffled copy (fixed seed: the same garment gives the same cylinder).
Circle min_enclosing_circle(std::vector<Vec2> p) {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (size_t i = p.size(); i > 1; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(p[i - 1], p[static_cast<size_t>(state >> 33) % i]);
  }
  Circle c;
  for (size_t i = 0; i < p.size(); ++i) {
    if (c.r >= 0 && c.contains(p[i])) continue;
    c = {p[i], 0};
    for (size_t j = 0; j < i; ++j) {
      if (c.contains(p[j])) continue;
      c = from2(p[i], p[j]);
      for (size_t k = 0; k < j; ++k)
        if (!c.contains(p[k])) c = from3(p[i], p[j], p[k]);
    }
  }
  return c;
}

}  // namespace

Cylinder fit_cylinder(const std::vector<Vec3>& points, Vec3 direction, std::optional<Vec3> origin) {
  Cylinder cyl;
  cyl.direction = norm(direction) > 0 ? normalized(direction) : Vec3{0, 1, 0};
  const Vec3 a = cyl.direction;
  // An orthonormal frame (e0, e1) of the plane normal to the axis.
  const Vec3 helper = std::abs(a.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  const Vec3 e0 = normalized(cross(helper, a));
  const Vec3 e1 = cross(a, e0);
  if (points.empty()) {
    cyl.origin_mm = origin.value_or(Vec3{});
    return cyl;
  }
  double hmin = std::numeric_limits<double>::infinity(), hmax = -hmin;
  std::vector<Vec2> flat;
  flat.reserve(points.size());
  for (Vec3 p : points) {
    hmin = std::min(hmin, dot(p, a));
    hmax = std::max(hmax, dot(p, a));
    flat.push_back({dot(p, e0), dot(p, e1)});
  }
  Vec2 centre;
  double radius = 0;
  if (origin) {
    centre = {dot(*origin, e0), dot(*origin, e1)};
    for (Vec2 q : flat) radius = std::max(radius, norm(q - centre));
  } else {
    const Circle c = min_enclosing_circle(flat);
    centre = c.c;
    radius = c.r;
  }
  // Origin on the axis at height 0 of the world frame's projection, then heights relative to it.
  cyl.origin_mm = e0 * centre.x + e1 * centre.y;
  if (origin) cyl.origin_mm = cyl.origin_mm + a * dot(*origin, a);
  const double h0 = dot(cyl.origin_mm, a);
  cyl.radius_mm = radius;
  cyl.min_height_mm = hmin - h0;
  cyl.max_height_mm = hmax - h0;
  return cyl;
}

}  // namespace tp::geometry
