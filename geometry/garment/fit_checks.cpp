// geometry/garment/fit_checks.cpp: stitch gaps, self-intersections, inside and distance to the body of a garment.
#include "geometry/garment/fit_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/design/internal/closest_point.h"

namespace tp::geometry {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Triangles of less area than this (mm^2) are degenerate: collapsed by merging, never tested.
constexpr double kDegenerateArea_mm2 = 1e-9;
// Box intersection's cutoff between streaming and recursing for the body crossings: a 20,000-
// triangle garment against a 91,000-triangle part of a body streamed its boxes in 0.19 s with
// CGAL's default (10), 0.04 s with 1,000.
constexpr std::ptrdiff_t kCrossingsBoxCutoff = 1000;

struct SoupTriangle {
  std::array<int, 3> v;
  int piece = 0;
};

std::vector<SoupTriangle> garment_triangles(const Garment& g, const std::vector<bool>* skip) {
  std::vector<SoupTriangle> out;
  for (size_t p = 0; p < g.pieces.size(); ++p) {
    if (skip && p < skip->size() && (*skip)[p]) continue;
    const GarmentPiece& gp = g.pieces[p];
    for (const auto& t : gp.mesh.triangles) {
      std::array<int, 3> v{gp.vertex_3d[t[0]], gp.vertex_3d[t[1]], gp.vertex_3d[t[2]]};
      if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
      const Vec3 a = g.vertices_mm[v[0]], b = g.vertices_mm[v[1]], c = g.vertices_mm[v[2]];
      if (0.5 * norm(cross(b - a, c - a)) < kDegenerateArea_mm2) continue;
      out.push_back({v, static_cast<int>(p)});
    }
  }
  return out;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  size_t k = static_cast<size_t>(std::ceil(q * static_cast<double>(v.size()))) - 1;
  return v[std::min(k, v.size() - 1)];
}

// The preview that shows a point best: the body frame has z to the front, x to the side.
const char* view_of(Vec3 p, const Box3& body_box) {
  double dx = p.x - 0.5 * (body_box.min.x + body_box.max.x), dz = p.z - 0.5 * (body_box.min.z + body_box.max.z);
  if (std::abs(dx) > std::abs(dz)) return "side";
  return dz >= 0 ? "front" : "back";
}

std::string fmt(double v, const char* spec = "%.1f") {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, v);
  return buf;
}

// "<n> <what> (<share> %<of>, limit <limit> %)": a count against its limit, a share of `total`.
std::string count_against_limit(int n, const std::string& what, int total, double limit, const char* of) {
  return std::to_string(n) + " " + what + " (" + fmt(100.0 * n / total, "%.2f") + " %" + of + ", limit " +
         fmt(100 * limit, "%.2f") + " %)";
}

// Index of the largest entry (the first on ties), or -1 when all are zero.
int worst_of(const std::vector<double>& v) {
  int best = -1;
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i] > 0 && (best < 0 || v[i] > v[static_cast<size_t>(best)])) best = static_cast<int>(i);
  return best;
}

}  // namespace

int count_self_intersections(const Garment& g, std::vector<int>* per_piece, const std::vector<bool>* skip) {
  const std::vector<SoupTriangle> tris = garment_triangles(g, skip);
  if (per_piece) per_piece->assign(g.pieces.size(), 0);
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, const SoupTriangle*>;
  std::vector<Box> boxes;
  boxes.reserve(tris.size());
  for (const SoupTriangle& t : tris) {
    CGAL::Bbox_3 bb;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = g.vertices_mm[t.v[k]];
      bb += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
    }
    boxes.emplace_back(bb, &t);
  }
  auto point = [&](int i) { const Vec3 p = g.vertices_mm[i]; return K::Point_3(p.x, p.y, p.z); };
  int count = 0;
  auto report = [&](const Box& a, const Box& b) {
    const SoupTriangle& ta = *a.handle();
    const SoupTriangle& tb = *b.handle();
    for (int i : ta.v)
      for (int j : tb.v)
        if (i == j) return;  // neighbours touch at a shared vertex or edge by construction
    K::Triangle_3 x(point(ta.v[0]), point(ta.v[1]), point(ta.v[2]));
    K::Triangle_3 y(point(tb.v[0]), point(tb.v[1]), point(tb.v[2]));
    if (!CGAL::do_intersect(x, y)) return;
    ++count;
    if (per_piece) {
      ++(*per_piece)[static_cast<size_t>(ta.piece)];
      ++(*per_piece)[static_cast<size_t>(tb.piece)];
    }
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report);
  return count;
}

int count_body_crossings(const Garment& g, const BodyMesh& body, std::vector<int>* per_piece,
                         const std::vector<bool>* skip) {
  const std::vector<SoupTriangle> tris = garment_triangles(g, skip);
  if (per_piece) per_piece->assign(g.pieces.size(), 0);
  // Handles 0..n-1 are the garment's triangles, n.. the body's.
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;
  auto triangle = [](Vec3 a, Vec3 b, Vec3 c) {
    return K::Triangle_3(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z), K::Point_3(c.x, c.y, c.z));
  };
  std::vector<K::Triangle_3> cloth, skin;
  std::vector<Box> cloth_boxes, skin_boxes;
  CGAL::Bbox_3 garment_box;
  for (const SoupTriangle& t : tris) {
    cloth.push_back(triangle(g.vertices_mm[t.v[0]], g.vertices_mm[t.v[1]], g.vertices_mm[t.v[2]]));
    cloth_boxes.emplace_back(cloth.back().bbox(), cloth.size() - 1);
    garment_box += cloth.back().bbox();
  }
  // Only the body's triangles within the garment's box can cross it (a top leaves the legs out).
  for (const auto& t : body.triangles) {
    const Vec3 a = body.vertices_mm[t[0]], b = body.vertices_mm[t[1]], c = body.vertices_mm[t[2]];
    if (0.5 * norm(cross(b - a, c - a)) < kDegenerateArea_mm2) continue;
    const K::Triangle_3 s = triangle(a, b, c);
    if (!CGAL::do_overlap(s.bbox(), garment_box)) continue;
    skin.push_back(s);
    skin_boxes.emplace_back(s.bbox(), tris.size() + skin.size() - 1);
  }
  std::vector<char> crossing(tris.size(), 0);
  CGAL::box_intersection_d(
      cloth_boxes.begin(), cloth_boxes.end(), skin_boxes.begin(), skin_boxes.end(),
      [&](const Box& a, const Box& b) {
        const size_t i = a.handle();
        if (!crossing[i] && CGAL::do_intersect(cloth[i], skin[b.handle() - tris.size()])) crossing[i] = 1;
      },
      kCrossingsBoxCutoff);
  int count = 0;
  for (size_t i = 0; i < tris.size(); ++i) {
    if (!crossing[i]) continue;
    ++count;
    if (per_piece) ++(*per_piece)[static_cast<size_t>(tris[i].piece)];
  }
  return count;
}

FitReport check_fit(const Pattern& pattern, const Garment& g, const BodySdf* body,
                    const std::vector<std::vector<double>>& stitch_gaps_mm, const FitLimits& limits) {
  FitReport r;
  r.vertices = static_cast<int>(g.vertices_mm.size());
  Box3 garment_box;
  for (const Vec3& v : g.vertices_mm) garment_box.add(v);
  const Box3 frame = body ? body->box() : garment_box;
  const size_t np = pattern.pieces.size();
  // Pieces sewn to no other piece are printed flat: listed, and left out of the checks.
  std::vector<bool> unsewn(np, true);
  for (const Stitch& st : pattern.stitches)
    if (st.a.piece != st.b.piece) unsewn[static_cast<size_t>(st.a.piece)] = unsewn[static_cast<size_t>(st.b.piece)] = false;
  if (pattern.stitches.empty()) unsewn.assign(np, false);
  for (size_t p = 0; p < np; ++p)
    if (unsewn[p]) r.unsewn_pieces.push_back(static_cast<int>(p));

  // Stitch gaps: every sewn vertex pair, before merging.
  std::vector<double> all_gaps;
  for (size_t s = 0; s < stitch_gaps_mm.size(); ++s) {
    for (double d : stitch_gaps_mm[s]) {
      if (r.worst_stitch < 0 || d > r.stitch_gap_max_mm) {
        r.stitch_gap_max_mm = d;
        r.worst_stitch = static_cast<int>(s);
      }
      all_gaps.push_back(d);
    }
  }
  r.stitches = static_cast<int>(stitch_gaps_mm.size());
  r.stitch_gap_p95_mm = percentile(all_gaps, 0.95);
  if (!all_gaps.empty() && r.stitch_gap_max_mm > limits.max_stitch_gap_mm && r.worst_stitch >= 0 &&
      r.worst_stitch < static_cast<int>(pattern.stitches.size())) {
    const Stitch& st = pattern.stitches[static_cast<size_t>(r.worst_stitch)];
    const GarmentPiece& gp = g.pieces[static_cast<size_t>(st.a.piece)];
    const auto& ev = gp.mesh.edge_vertices[static_cast<size_t>(st.a.edge)];
    Vec3 at = ev.empty() ? garment_box.min : g.vertices_mm[gp.vertex_3d[ev[ev.size() / 2]]];
    r.failures.push_back({"stitch_gap", "stitch gap " + fmt(r.stitch_gap_max_mm) + " mm (limit " + fmt(limits.max_stitch_gap_mm) +
                         " mm) at stitch " + std::to_string(r.worst_stitch) + ", " +
                         describe_edge(pattern, st.a.piece, st.a.edge) + " to " +
                         describe_edge(pattern, st.b.piece, st.b.edge) + ": not sewn together", view_of(at, frame)});
  }

  // Self-intersections, with the piece most involved.
  std::vector<int> si_piece;
  r.self_intersections = count_self_intersections(g, &si_piece, &unsewn);
  const std::vector<SoupTriangle> tris = garment_triangles(g, &unsewn);
  r.triangles = static_cast<int>(tris.size());
  auto piece_centre = [&](int p) {
    Vec3 c{};
    const GarmentPiece& gp = g.pieces[static_cast<size_t>(p)];
    for (int v : gp.vertex_3d) c += g.vertices_mm[v];
    return gp.vertex_3d.empty() ? c : c / static_cast<double>(gp.vertex_3d.size());
  };
  if (r.triangles > 0 && r.self_intersections > limits.max_self_intersections * r.triangles) {
    std::vector<double> w(si_piece.begin(), si_piece.end());
    int p = worst_of(w);
    r.failures.push_back({"self_intersections",
                          count_against_limit(r.self_intersections, "self-intersecting triangle pairs", r.triangles,
                                              limits.max_self_intersections, " of triangles") +
                              ": tangled, most in piece '" + pattern.pieces[static_cast<size_t>(p)].name + "'",
                          view_of(piece_centre(p), frame)});
  }
  if (!body) {
    r.pass = r.failures.empty();
    return r;
  }

  // Inside the body (signed, from the SDF) and distance to it (exact, from the body's triangles).
  internal::ClosestPointIndex surface(body->mesh().vertices_mm, body->mesh().triangles);
  std::vector<double> dist(g.vertices_mm.size());
  std::vector<double> inside_piece(np, 0);
  std::vector<char> inside(g.vertices_mm.size(), 0);
  // Vertices of sewn pieces only (a seam vertex belongs to every piece it joins).
  std::vector<char> sewn_vertex(g.vertices_mm.size(), 0);
  for (size_t p = 0; p < np && p < g.pieces.size(); ++p)
    if (!unsewn[p])
      for (int v : g.pieces[p].vertex_3d) sewn_vertex[static_cast<size_t>(v)] = 1;
  dist.clear();
  for (size_t i = 0; i < g.vertices_mm.size(); ++i) {
    if (!sewn_vertex[i]) continue;
    dist.push_back(surface.nearest(g.vertices_mm[i]).distance_mm);
    inside[i] = body->query(g.vertices_mm[i]).distance_mm < 0;
    r.inside_body += inside[i];
  }
  for (size_t p = 0; p < np && p < g.pieces.size(); ++p)
    for (int v : g.pieces[p].vertex_3d) inside_piece[p] += inside[static_cast<size_t>(v)];
  r.body_distance_p50_mm = percentile(dist, 0.5);
  r.body_distance_p95_mm = percentile(dist, 0.95);
  if (r.vertices > 0 && r.inside_body > limits.max_inside_body * r.vertices) {
    int p = worst_of(inside_piece);
    r.failures.push_back(
        {"inside_body",
         count_against_limit(r.inside_body, "vertices inside the body", r.vertices, limits.max_inside_body, "") +
             ", most of piece '" + pattern.pieces[static_cast<size_t>(p)].name + "'",
         view_of(piece_centre(p), frame)});
  }
  // Triangles the body pokes through (their vertices may all be outside it).
  std::vector<int> crossing_piece;
  r.body_crossings = count_body_crossings(g, body->mesh(), &crossing_piece, &unsewn);
  if (r.triangles > 0 && r.body_crossings > limits.max_body_crossings * r.triangles) {
    int p = worst_of(std::vector<double>(crossing_piece.begin(), crossing_piece.end()));
    r.failures.push_back({"body_crossings",
                          count_against_limit(r.body_crossings, "triangles cross the body's surface", r.triangles,
                                              limits.max_body_crossings, " of triangles") +
                              ", most of piece '" + pattern.pieces[static_cast<size_t>(p)].name +
                              "': the body shows through the cloth",
                          view_of(piece_centre(p), frame)});
  }

  // Area farther than the limit distance from the body (by triangle centroid).
  double area = 0, off = 0;
  std::vector<double> off_piece(np, 0);
  for (const SoupTriangle& t : tris) {
    const Vec3 a = g.vertices_mm[t.v[0]], b = g.vertices_mm[t.v[1]], c = g.vertices_mm[t.v[2]];
    double ar = 0.5 * norm(cross(b - a, c - a));
    area += ar;
    if (surface.nearest((a + b + c) / 3.0).distance_mm > limits.off_body_distance_mm) {
      off += ar;
      off_piece[static_cast<size_t>(t.piece)] += ar;
    }
  }
  r.off_body = area > 0 ? off / area : 0;
  if (r.off_body > limits.max_off_body) {
    int p = worst_of(off_piece);
    r.failures.push_back({"off_body",
                          fmt(100 * r.off_body) + " % of the garment's area is farther than " +
                              fmt(limits.off_body_distance_mm, "%.0f") + " mm from the body (limit " +
                              fmt(100 * limits.max_off_body) + " %; body distance p95 " + fmt(r.body_distance_p95_mm) +
                              " mm), most of piece '" + pattern.pieces[static_cast<size_t>(p)].name + "': not on the body",
                          view_of(piece_centre(p), frame)});
  }
  r.pass = r.failures.empty();
  return r;
}

}  // namespace tp::geometry
