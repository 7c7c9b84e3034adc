// geometry/mesh/triangulate_polygon.cpp: CGAL constrained Delaunay meshing with fixed boundary vertices.
#include "geometry/mesh/triangulate_polygon.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <string>

namespace tp::geometry {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Creation number of the next vertex (per thread: a piece is meshed on one thread).
std::uint64_t next_vertex_serial() {
  thread_local std::uint64_t next = 0;
  return next++;
}

// A mesh vertex that knows when it was created. CGAL's Lloyd optimiser keeps the moving vertices
// in a std::set<Vertex_handle> and moves them in its order; handles compare by address, so the
// mesh depended on where the heap put each vertex block (another run, other threads, other load:
// another mesh). Ordering handles by creation (std::less below) makes the order, and the mesh, a
// function of the outline and the options alone.
template <class Gt, class Base = CGAL::Delaunay_mesh_vertex_base_2<Gt>>
struct SerialVertex : Base {
  template <class Tds2>
  struct Rebind_TDS {
    using Other = SerialVertex<Gt, typename Base::template Rebind_TDS<Tds2>::Other>;
  };
  using Base::Base;
  std::uint64_t serial = next_vertex_serial();
};

using Vb = SerialVertex<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, Criteria>;

}  // namespace
}  // namespace tp::geometry

// Vertex handles of the mesher in creation order (see SerialVertex), never by address.
template <>
struct std::less<tp::geometry::Cdt::Vertex_handle> {
  bool operator()(const tp::geometry::Cdt::Vertex_handle& a, const tp::geometry::Cdt::Vertex_handle& b) const {
    if (a == b) return false;
    if (a == tp::geometry::Cdt::Vertex_handle() || b == tp::geometry::Cdt::Vertex_handle())
      return a == tp::geometry::Cdt::Vertex_handle();
    return a->serial < b->serial;
  }
};

namespace tp::geometry {
namespace {

// True when segments ab and cd cross at a point interior to both.
bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

}  // namespace

Result<PieceMesh> triangulate_polygon(const std::vector<Vec2>& ring, const TriangulateOptions& options) {
  const int n = static_cast<int>(ring.size());
  if (n < 3) return fail(ErrorCode::kMeshing, "outline has fewer than 3 points");
  if (!(options.target_edge_mm > 0)) return fail(ErrorCode::kInvalidArgument, "target edge length must be > 0 mm");

  // A self-intersecting ring has no inside; find crossings first (O(n^2) is fine for outlines).
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_cross(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n]))
        return fail(ErrorCode::kMeshing, "outline segments " + std::to_string(i) + " and " + std::to_string(j) + " cross");
    }

  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(n);
  for (const Vec2& p : ring) handles.push_back(cdt.insert(Cdt::Point(p.x, p.y)));
  if (static_cast<int>(cdt.number_of_vertices()) != n)
    return fail(ErrorCode::kMeshing, "outline has duplicate points");
  try {
    for (int i = 0; i < n; ++i) cdt.insert_constraint(handles[i], handles[(i + 1) % n]);
  } catch (const std::exception& e) {
    return fail(ErrorCode::kMeshing, std::string("outline constraints intersect: ") + e.what());
  }

  // Refine the inside (faces not reachable from infinity without crossing the outline) to the
  // size bound; boundary segments are never split, so seam vertices stay matched.
  // CGAL's shape bound is sin^2 of the smallest angle allowed.
  const double sin_min = std::sin(options.min_angle_deg * std::numbers::pi / 180.0);
  Mesher mesher(cdt, Criteria(sin_min * sin_min, options.target_edge_mm));
  mesher.refine_mesh();
  if (options.smoothing_iterations > 0)
    CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = options.smoothing_iterations);

  PieceMesh mesh;
  std::map<Cdt::Vertex_handle, int> index;
  for (int i = 0; i < n; ++i) {
    index[handles[i]] = i;
    mesh.vertices_mm.push_back(ring[i]);
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      auto v = f->vertex(k);
      auto [it, inserted] = index.emplace(v, static_cast<int>(mesh.vertices_mm.size()));
      if (inserted) mesh.vertices_mm.push_back({v->point().x(), v->point().y()});
      tri[k] = it->second;
    }
    // CGAL faces are counter-clockwise already; keep the check for clockwise input rings.
    Vec2 a = mesh.vertices_mm[tri[0]], b = mesh.vertices_mm[tri[1]], c = mesh.vertices_mm[tri[2]];
    if (cross(b - a, c - a) < 0) std::swap(tri[1], tri[2]);
    mesh.triangles.push_back(tri);
  }
  if (mesh.triangles.empty()) return fail(ErrorCode::kMeshing, "outline encloses no triangle");

  // Every boundary vertex must be the ring's own: count vertices on constrained edges.
  int on_boundary = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (cdt.are_there_incident_constraints(v)) ++on_boundary;
  if (on_boundary != n)
    return fail(ErrorCode::kMeshing, "refinement added " + std::to_string(on_boundary - n) + " boundary vertices");
  return mesh;
}

}  // namespace tp::geometry
