// tests/geometry/nesting/layout_checker.h: an exact, engine-independent check of nested layouts:
// pieces transformed here from their placements, interiors compared with CGAL's exact kernel.
#pragma once

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace tp::test {

/// A point list (x, y) in mm; the engine's types are deliberately not used here.
using Pts = std::vector<std::pair<double, double>>;

/// Maps a piece outline: mirror x -> -x (if set), rotate counter-clockwise by `deg` about the
/// origin, translate. Written out here, independent of the engine's own transform code.
inline Pts transform_piece(const Pts& pts, double deg, bool mirror, double tx, double ty) {
  const double r = deg * std::numbers::pi / 180.0, c = std::cos(r), s = std::sin(r);
  Pts out;
  for (auto [x, y] : pts) {
    if (mirror) x = -x;
    out.push_back({c * x - s * y + tx, s * x + c * y + ty});
  }
  return out;
}

/// What the check found.
struct LayoutReport {
  int overlaps = 0;        ///< pairs whose interiors share positive area (touching is fine)
  int outside = 0;         ///< vertices outside the allowed region
  int too_close = 0;       ///< pairs nearer than the required gap
  double min_distance = 1e300;  ///< smallest distance between two pieces' boundaries
  std::string first;       ///< description of the first problem
  bool ok() const { return overlaps == 0 && outside == 0 && too_close == 0; }
};

namespace detail {

using K = CGAL::Exact_predicates_exact_constructions_kernel;

inline CGAL::Polygon_2<K> exact_polygon(const Pts& pts) {
  CGAL::Polygon_2<K> p;
  for (auto [x, y] : pts) p.push_back(K::Point_2(x, y));
  if (p.size() > 1 && p[0] == p[p.size() - 1]) p.erase(p.vertices_end() - 1);
  if (p.is_clockwise_oriented()) p.reverse_orientation();
  return p;
}

inline double segment_distance(std::pair<double, double> a, std::pair<double, double> b, std::pair<double, double> p) {
  const double dx = b.first - a.first, dy = b.second - a.second;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.first - a.first) * dx + (p.second - a.second) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.first - (a.first + t * dx), p.second - (a.second + t * dy));
}

// Boundary distance of two polygons known not to overlap (vertex to edge both ways).
inline double boundary_distance(const Pts& a, const Pts& b) {
  double d = 1e300;
  for (int pass = 0; pass < 2; ++pass) {
    const Pts& p = pass ? b : a;
    const Pts& q = pass ? a : b;
    for (auto v : p)
      for (size_t i = 0; i < q.size(); ++i) d = std::min(d, segment_distance(q[i], q[(i + 1) % q.size()], v));
  }
  return d;
}

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
};

inline Box box_of(const Pts& p) {
  Box b;
  for (auto [x, y] : p) {
    b.x0 = std::min(b.x0, x);
    b.y0 = std::min(b.y0, y);
    b.x1 = std::max(b.x1, x);
    b.y1 = std::max(b.y1, y);
  }
  return b;
}

}  // namespace detail

/// Checks placed pieces (already transformed) against each other and against `hazards`: no two
/// interiors overlap (exact: the regularised intersection has zero area), every vertex lies in
/// [x0, x1] x [y0, y1], and boundaries are at least `gap` apart (to 1e-9 relative).
inline LayoutReport check_layout(const std::vector<Pts>& pieces, double x0, double y0, double x1, double y1,
                                 double gap, const std::vector<Pts>& hazards = {}) {
  using namespace detail;
  LayoutReport r;
  std::vector<CGAL::Polygon_2<K>> exact;
  std::vector<Box> boxes;
  for (size_t i = 0; i < pieces.size(); ++i) {
    for (auto [x, y] : pieces[i]) {
      if (x < x0 || x > x1 || y < y0 || y > y1) {
        if (r.outside++ == 0)
          r.first = "piece " + std::to_string(i) + " outside the region at (" + std::to_string(x) + ", " +
                    std::to_string(y) + ")";
      }
    }
  }
  std::vector<Pts> all = pieces;
  all.insert(all.end(), hazards.begin(), hazards.end());
  for (const Pts& p : all) {
    exact.push_back(exact_polygon(p));
    boxes.push_back(box_of(p));
  }
  const double tol = 1e-9 * std::max({1.0, std::fabs(x1), std::fabs(y1)});
  for (size_t i = 0; i < pieces.size(); ++i) {
    for (size_t j = i + 1; j < all.size(); ++j) {
      const Box &a = boxes[i], &b = boxes[j];
      if (a.x0 > b.x1 + gap || b.x0 > a.x1 + gap || a.y0 > b.y1 + gap || b.y0 > a.y1 + gap) continue;
      std::vector<CGAL::Polygon_with_holes_2<K>> common;
      CGAL::intersection(exact[i], exact[j], std::back_inserter(common));
      K::FT area = 0;
      for (const auto& c : common) {
        area += c.outer_boundary().area();
        for (auto h = c.holes_begin(); h != c.holes_end(); ++h) area += h->area();
      }
      if (area > 0) {
        if (r.overlaps++ == 0)
          r.first = "piece " + std::to_string(i) + " overlaps " + (j < pieces.size() ? "piece " : "hazard ") +
                    std::to_string(j < pieces.size() ? j : j - pieces.size());
        continue;
      }
      const double d = boundary_distance(all[i], all[j]);
      r.min_distance = std::min(r.min_distance, d);
      if (gap > 0 && d < gap - tol) {
        if (r.too_close++ == 0) r.first = "pieces " + std::to_string(i) + " and " + std::to_string(j) + " closer than the gap";
      }
    }
  }
  return r;
}

}  // namespace tp::test
