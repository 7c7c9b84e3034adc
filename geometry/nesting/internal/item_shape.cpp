// geometry/nesting/internal/item_shape.cpp: posing collision shapes, hull areas and diameters.
#include "geometry/nesting/internal/item_shape.h"

#include <algorithm>
#include <cmath>

namespace tp::geometry::nesting {

OrientedShape orient(const ItemShape& shape, const Pose& pose) {
  OrientedShape o;
  const double c = std::cos(pose.angle_rad), s = std::sin(pose.angle_rad);
  o.pts.reserve(shape.outline.size());
  for (Vec2 p : shape.outline) {
    o.pts.push_back(apply_pose(p, c, s, pose.mirror));
    o.box.add(o.pts.back());
  }
  // A mirror reverses the winding; keep the outline counter-clockwise.
  if (pose.mirror) std::reverse(o.pts.begin(), o.pts.end());
  o.poles.reserve(shape.poles.size());
  for (const Circle& k : shape.poles) o.poles.push_back({apply_pose(k.c, c, s, pose.mirror), k.r});
  o.original_max_x = -1e300;
  o.original_min_x = 1e300;
  for (Vec2 p : shape.original) {
    const double x = apply_pose(p, c, s, pose.mirror).x;
    o.original_max_x = std::max(o.original_max_x, x);
    o.original_min_x = std::min(o.original_min_x, x);
  }
  return o;
}

double convex_hull_area(const std::vector<Vec2>& pts) {
  // Andrew's monotone chain.
  std::vector<Vec2> p = pts;
  std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return 0;
  std::vector<Vec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 1] - h[k - 2], p[i - 1] - h[k - 2]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return std::fabs(signed_area(h));
}

double point_set_diameter(const std::vector<Vec2>& pts) {
  double d = 0;
  for (size_t i = 0; i < pts.size(); ++i)
    for (size_t j = i + 1; j < pts.size(); ++j) d = std::max(d, norm(pts[i] - pts[j]));
  return d;
}

}  // namespace tp::geometry::nesting
