// geometry/sewing/internal/cloth_model.cpp: masses, rest shapes and bending stencils of a cloth.
#include "geometry/sewing/internal/cloth_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>

namespace tp::geometry::internal {
namespace {

/// A bending hinge shorter than this (mm), or with a wing of squared doubled area below
/// kHingeMinArea2 (mm^4), has no defined angle: it exerts no force.
constexpr double kHingeMinLength_mm = 1e-12;
constexpr double kHingeMinArea2 = 1e-20;
/// A rest triangle whose 2D determinant (twice its area, mm^2) is below this is skipped.
constexpr double kDegenerateRestArea = 1e-9;

// Bending rigidity from micro-newton metres to the solver's g mm^2 / s^2.
constexpr double kUNmToGmm2s2 = 1e3;

struct HalfEdge {
  int lo, hi, tri, opposite;
  bool forward;  ///< the triangle's winding runs lo -> hi
  int chart_lo, chart_hi;  ///< the ends' vertices in the triangle's chart (its piece's 2D mesh)
};

// The length of edge (lo, hi) in the rest shape of triangle `t`.
double rest_length_mm(const RestTriangle& t, int lo, int hi) {
  int a = 0, b = 0;
  for (int k = 0; k < 3; ++k) {
    if (t.v[k] == lo) a = k;
    if (t.v[k] == hi) b = k;
  }
  return norm(t.rest_mm[a] - t.rest_mm[b]);
}

// An edge joining two charts (a sewn seam segment): its ends, the pieces of its two sides
// (piece_a <= piece_b) and its rest length in each.
struct JoinEdge {
  int lo, hi, piece_a, piece_b;
  double la, lb;
};

struct GatheredEnd {
  int piece, vertex;
  double ratio;
};

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Per join edge, whether its run is plain: the joins between two different pieces that chain
// through shared vertices, their sides' summed lengths agreeing within kPlainSeamSegment (the
// rule XPBD sewing applies to a whole stitch). A dart's joins (one piece) are judged alone.
std::vector<uint8_t> plain_runs(const std::vector<JoinEdge>& joins, int vertices) {
  const int m = static_cast<int>(joins.size());
  std::vector<int> parent(m);
  for (int j = 0; j < m; ++j) parent[j] = j;
  // The first join of each piece pair seen at a vertex; later ones at that vertex join its run.
  std::vector<std::vector<std::pair<std::pair<int, int>, int>>> at(vertices);
  for (int j = 0; j < m; ++j) {
    const JoinEdge& e = joins[j];
    if (e.piece_a == e.piece_b) continue;
    for (int v : {e.lo, e.hi}) {
      bool met = false;
      for (const auto& [pair, first] : at[v])
        if (pair == std::make_pair(e.piece_a, e.piece_b)) {
          parent[find_root(parent, j)] = find_root(parent, first);
          met = true;
        }
      if (!met) at[v].push_back({{e.piece_a, e.piece_b}, j});
    }
  }
  std::vector<double> sum_a(m, 0.0), sum_b(m, 0.0);
  for (int j = 0; j < m; ++j) {
    const int r = find_root(parent, j);
    sum_a[r] += joins[j].la, sum_b[r] += joins[j].lb;
  }
  std::vector<uint8_t> plain(m, 0);
  for (int j = 0; j < m; ++j) {
    if (joins[j].piece_a == joins[j].piece_b) continue;
    const int r = find_root(parent, j);
    plain[j] = plain_seam_lengths(sum_a[r], sum_b[r]);
  }
  return plain;
}

}  // namespace

double dihedral_angle(const std::vector<Vec3>& x, const BendStencil& s, std::array<Vec3, 4>* grad) {
  const Vec3 a = x[s.a], b = x[s.b], c = x[s.c], d = x[s.d];
  const Vec3 e = b - a;
  const double le = norm(e);
  // Normals of (a, b, c) and (b, a, d), both following their triangle's winding.
  const Vec3 n1 = cross(e, c - a), n2 = cross(d - a, e);
  const double q1 = dot(n1, n1), q2 = dot(n2, n2);
  if (le < kHingeMinLength_mm || q1 < kHingeMinArea2 || q2 < kHingeMinArea2) {
    if (grad) grad->fill(Vec3{});
    return s.rest_angle;
  }
  const double angle = std::atan2(dot(cross(n1, n2), e) / le, dot(n1, n2));
  if (grad) {
    // Gradients of the dihedral angle (Bridson et al. 2003; Wardetzky et al. 2007).
    const Vec3 gc = n1 * (-le / q1), gd = n2 * (-le / q2);
    const double sc = dot(c - a, e) / (le * le), sd = dot(d - a, e) / (le * le);
    (*grad)[2] = gc;
    (*grad)[3] = gd;
    (*grad)[0] = gc * (sc - 1) + gd * (sd - 1);
    (*grad)[1] = gc * (-sc) + gd * (-sd);
  }
  return angle;
}

ClothModel build_cloth_model(const Garment& g, const ClothMaterial& m) {
  ClothModel cm;
  cm.x_mm = g.vertices_mm;
  const int n = static_cast<int>(cm.x_mm.size());
  std::vector<double> mass(n, 0.0);
  cm.vertex_piece.assign(n, -1);
  cm.vertex_rest_mm.assign(n, Vec2{});
  std::vector<int> tri_piece;
  std::vector<std::array<int, 3>> tri_chart;  // per triangle, its corners in its piece's 2D mesh
  double edge_sum = 0;
  int edge_count = 0;
  for (size_t p = 0; p < g.pieces.size(); ++p) {
    const GarmentPiece& gp = g.pieces[p];
    for (size_t v = 0; v < gp.vertex_3d.size(); ++v)
      if (cm.vertex_piece[gp.vertex_3d[v]] < 0) {
        cm.vertex_piece[gp.vertex_3d[v]] = static_cast<int>(p);
        cm.vertex_rest_mm[gp.vertex_3d[v]] = gp.mesh.vertices_mm[v];
      }
    for (const auto& t : gp.mesh.triangles) {
      RestTriangle rt;
      for (int k = 0; k < 3; ++k) rt.v[k] = gp.vertex_3d[t[k]];
      if (rt.v[0] == rt.v[1] || rt.v[1] == rt.v[2] || rt.v[0] == rt.v[2]) continue;
      const Vec2 r0 = gp.mesh.vertices_mm[t[0]], r1 = gp.mesh.vertices_mm[t[1]], r2 = gp.mesh.vertices_mm[t[2]];
      const Vec2 e1 = r1 - r0, e2 = r2 - r0;
      const double det = cross(e1, e2);
      if (std::abs(det) < kDegenerateRestArea) continue;
      const Vec2 centroid = (r0 + r1 + r2) / 3.0;
      rt.rest_mm = {r0 - centroid, r1 - centroid, r2 - centroid};
      rt.dm_inv[0][0] = e2.y / det, rt.dm_inv[0][1] = -e2.x / det;
      rt.dm_inv[1][0] = -e1.y / det, rt.dm_inv[1][1] = e1.x / det;
      rt.area_mm2 = 0.5 * std::abs(det);
      for (int k = 0; k < 3; ++k) mass[rt.v[k]] += rt.area_mm2 / 3 * m.density_g_m2 * 1e-6;
      edge_sum += norm(e1) + norm(e2) + norm(r2 - r1), edge_count += 3;
      cm.triangles.push_back(rt);
      tri_piece.push_back(static_cast<int>(p));
      tri_chart.push_back(t);
    }
  }
  cm.mean_edge_mm = edge_count ? edge_sum / edge_count : 0;
  cm.inv_mass.resize(n);
  for (int i = 0; i < n; ++i) cm.inv_mass[i] = mass[i] > 0 ? 1 / mass[i] : 0;

  // Half-edges sorted by their undirected edge: unique edges, and a stencil per edge with two.
  std::vector<HalfEdge> he;
  for (size_t f = 0; f < cm.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = cm.triangles[f].v[k], j = cm.triangles[f].v[(k + 1) % 3], o = cm.triangles[f].v[(k + 2) % 3];
      const int ci = tri_chart[f][k], cj = tri_chart[f][(k + 1) % 3];
      he.push_back({std::min(i, j), std::max(i, j), static_cast<int>(f), o, i < j, i < j ? ci : cj, i < j ? cj : ci});
    }
  std::sort(he.begin(), he.end(), [](const HalfEdge& p, const HalfEdge& q) {
    return std::tie(p.lo, p.hi, p.tri) < std::tie(q.lo, q.hi, q.tri);
  });
  const double rigidity = m.bending_rigidity_uN_m * kUNmToGmm2s2;
  std::vector<JoinEdge> joins;
  for (size_t k = 0; k < he.size();) {
    size_t e = k;
    while (e < he.size() && he[e].lo == he[k].lo && he[e].hi == he[k].hi) ++e;
    cm.edges.push_back({he[k].lo, he[k].hi});
    // A sewn seam segment: the edge of two charts (two pieces, or two sides of one piece, a dart).
    if (e - k == 2 && (tri_piece[he[k].tri] != tri_piece[he[k + 1].tri] || he[k].chart_lo != he[k + 1].chart_lo ||
                       he[k].chart_hi != he[k + 1].chart_hi)) {
      // Sides ordered by piece, so a seam's segments add up side by side.
      const bool swap = tri_piece[he[k].tri] > tri_piece[he[k + 1].tri];
      const HalfEdge& h0 = swap ? he[k + 1] : he[k];
      const HalfEdge& h1 = swap ? he[k] : he[k + 1];
      joins.push_back({h0.lo, h0.hi, tri_piece[h0.tri], tri_piece[h1.tri],
                       rest_length_mm(cm.triangles[h0.tri], h0.lo, h0.hi),
                       rest_length_mm(cm.triangles[h1.tri], h0.lo, h0.hi)});
    }
    if (e - k == 2 && rigidity > 0) {
      // Orient the stencil along the first triangle's winding.
      const HalfEdge& h1 = he[k];
      const HalfEdge& h2 = he[k + 1];
      BendStencil s;
      s.a = h1.forward ? h1.lo : h1.hi;
      s.b = h1.forward ? h1.hi : h1.lo;
      s.c = h1.opposite;
      s.d = h2.opposite;
      const double area = cm.triangles[h1.tri].area_mm2 + cm.triangles[h2.tri].area_mm2;
      const double len2 = dot(cm.x_mm[s.b] - cm.x_mm[s.a], cm.x_mm[s.b] - cm.x_mm[s.a]);
      // Discrete-shell weight 3 |e|^2 / (A1 + A2) (Grinspun et al. 2003).
      s.compliance = 1 / (rigidity * 3 * len2 / area);
      // Inside a piece the fabric rests flat (sign from windings that agree); across a seam
      // (or where the windings disagree) the sewn angle is the rest angle.
      const bool same_piece = tri_piece[h1.tri] == tri_piece[h2.tri] && h1.forward != h2.forward;
      s.rest_angle = same_piece ? 0.0 : dihedral_angle(cm.x_mm, s, nullptr);
      cm.bends.push_back(s);
    }
    k = e;
  }
  // A segment is plain when its sides agree, or when the run of segments it belongs to does:
  // the mesh puts a seam's vertices evenly on each side, so the segment at a seam's end can
  // differ by a few per cent while the seam is plain (bella's sleeve caps, 9.60 mm against 9.95
  // mm at the underarm point: that segment, left to the membrane, draped 34 % long).
  const std::vector<uint8_t> plain_run = plain_runs(joins, n);
  std::vector<GatheredEnd> gathered;
  for (size_t j = 0; j < joins.size(); ++j) {
    const JoinEdge& e = joins[j];
    if (plain_run[j] || plain_seam_lengths(e.la, e.lb)) {
      cm.seam_edges.push_back({e.lo, e.hi, 0.5 * (e.la + e.lb)});
    } else {
      const int longer = e.la > e.lb ? e.piece_a : e.piece_b;
      const double ratio = std::min(e.la, e.lb) / std::max(e.la, e.lb);
      gathered.push_back({longer, e.lo, ratio});
      gathered.push_back({longer, e.hi, ratio});
    }
  }
  // The longer sides of eased seams: their piece's triangles at each end vertex are gathered.
  std::vector<std::vector<const GatheredEnd*>> gathered_at(n);
  for (const GatheredEnd& end : gathered) gathered_at[end.vertex].push_back(&end);
  for (size_t f = 0; f < cm.triangles.size(); ++f)
    for (int v : cm.triangles[f].v)
      for (const GatheredEnd* end : gathered_at[v])
        if (end->piece == tri_piece[f]) {
          double& ms = cm.triangles[f].min_stretch;
          ms = ms > 0 ? std::min(ms, end->ratio * kGatherSlack) : end->ratio * kGatherSlack;
        }
  return cm;
}

void mark_gathered(std::vector<RestTriangle>& triangles, const std::vector<int>& seam_vertices, double min_stretch) {
  for (RestTriangle& t : triangles)
    for (int v : t.v)
      if (std::binary_search(seam_vertices.begin(), seam_vertices.end(), v)) {
        t.min_stretch = t.min_stretch > 0 ? std::min(t.min_stretch, min_stretch) : min_stretch;
        break;
      }
}

}  // namespace tp::geometry::internal
