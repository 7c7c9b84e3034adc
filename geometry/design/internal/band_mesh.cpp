// geometry/design/internal/band_mesh.cpp: constrained Delaunay triangulation of the allowance band.
#include "geometry/design/internal/band_mesh.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace tp::geometry::internal {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>,
                                                 CGAL::Constrained_triangulation_face_base_2<K>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_intersections_tag>;

void insert_loop(Cdt& cdt, const Polygon& poly) {
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    if (a == b) continue;
    cdt.insert_constraint(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y));
  }
}

}  // namespace

bool inside_polygon(const Polygon& poly, Vec2 p) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

std::vector<std::array<Vec2, 3>> triangulate_band(const Polygon& inner, const Polygon& outer, double max_edge_mm,
                                                  const std::vector<std::array<Vec2, 2>>& cuts) {
  std::vector<std::array<Vec2, 3>> out;
  if (inner.size() < 3 || outer.size() < 3) return out;
  Polygon dense;
  for (size_t i = 0; i < outer.size(); ++i) {
    const Vec2 a = outer[i], b = outer[(i + 1) % outer.size()];
    const int parts = max_edge_mm > 0 ? std::max(1, static_cast<int>(std::ceil(norm(b - a) / max_edge_mm))) : 1;
    for (int k = 0; k < parts; ++k) dense.push_back(a + (b - a) * (static_cast<double>(k) / parts));
  }
  Cdt cdt;
  insert_loop(cdt, dense);
  insert_loop(cdt, inner);
  for (const auto& c : cuts)
    if (c[0] != c[1]) cdt.insert_constraint(K::Point_2(c[0].x, c[0].y), K::Point_2(c[1].x, c[1].y));
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    std::array<Vec2, 3> t;
    for (int k = 0; k < 3; ++k) {
      const auto& p = f->vertex(k)->point();
      t[static_cast<size_t>(k)] = {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
    }
    const Vec2 c = (t[0] + t[1] + t[2]) / 3.0;
    // Faces never straddle a constraint, so the centroid decides which region a face is in.
    if (!inside_polygon(dense, c) || inside_polygon(inner, c)) continue;
    if (cross(t[1] - t[0], t[2] - t[0]) < 0) std::swap(t[1], t[2]);
    if (cross(t[1] - t[0], t[2] - t[0]) <= 0) continue;
    out.push_back(t);
  }
  return out;
}

}  // namespace tp::geometry::internal
