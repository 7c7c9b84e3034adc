// geometry/design/internal/garment_surface.cpp: validation, seam partners and outward normals.
#include "geometry/design/internal/garment_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <string>

namespace tp::geometry::internal {
namespace {

std::string piece_label(const Pattern& pattern, int i) {
  return "piece '" + pattern.pieces[static_cast<size_t>(i)].name + "'";
}

// Boundary loop from the per-edge vertex lists (each edge's last vertex is the next one's first).
Status build_loop(const Pattern& pattern, int pi, PieceChart& chart) {
  const GarmentPiece& gp = *chart.piece;
  const auto& ev = gp.mesh.edge_vertices;
  const int nv = static_cast<int>(gp.mesh.vertices_mm.size());
  const std::string who = piece_label(pattern, pi);
  if (ev.empty()) return fail(ErrorCode::kInvalidArgument, who + ": mesh.edge_vertices is empty");
  const size_t n_edges = pattern.pieces[static_cast<size_t>(pi)].edges.size();
  if (ev.size() != n_edges)
    return fail(ErrorCode::kInvalidArgument, who + ": mesh.edge_vertices has " + std::to_string(ev.size()) +
                                                 " edges, the pattern piece has " + std::to_string(n_edges));
  for (size_t e = 0; e < ev.size(); ++e) {
    const auto& list = ev[e];
    const auto& next = ev[(e + 1) % ev.size()];
    if (list.size() < 2)
      return fail(ErrorCode::kInvalidArgument, who + ": mesh.edge_vertices[" + std::to_string(e) + "] has fewer than 2 vertices");
    for (int v : list)
      if (v < 0 || v >= nv)
        return fail(ErrorCode::kInvalidArgument, who + ": mesh.edge_vertices[" + std::to_string(e) + "] refers to vertex " +
                                                     std::to_string(v) + " of " + std::to_string(nv));
    if (list.back() != next.front())
      return fail(ErrorCode::kInvalidArgument, who + ": mesh.edge_vertices[" + std::to_string(e) +
                                                   "] does not end where the next edge starts");
    for (size_t k = 0; k + 1 < list.size(); ++k) {
      BoundarySegment s;
      s.a = list[k];
      s.b = list[k + 1];
      s.edge = static_cast<int>(e);
      chart.loop.push_back(list[k]);
      chart.segments.push_back(s);
    }
  }
  return {};
}

Status check_piece(const Pattern& pattern, int pi, const GarmentPiece& gp, size_t n3d) {
  const std::string who = piece_label(pattern, pi);
  const auto& m = gp.mesh;
  if (m.vertices_mm.empty() || m.triangles.empty())
    return fail(ErrorCode::kInvalidArgument, who + ": mesh has no triangles");
  if (gp.vertex_3d.size() != m.vertices_mm.size())
    return fail(ErrorCode::kInvalidArgument, who + ": vertex_3d has " + std::to_string(gp.vertex_3d.size()) +
                                                 " entries for " + std::to_string(m.vertices_mm.size()) + " mesh vertices");
  for (size_t i = 0; i < gp.vertex_3d.size(); ++i)
    if (gp.vertex_3d[i] < 0 || static_cast<size_t>(gp.vertex_3d[i]) >= n3d)
      return fail(ErrorCode::kInvalidArgument, who + ": vertex_3d[" + std::to_string(i) + "] = " +
                                                   std::to_string(gp.vertex_3d[i]) + " is not a garment vertex");
  const int nv = static_cast<int>(m.vertices_mm.size());
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    for (int v : m.triangles[t])
      if (v < 0 || v >= nv)
        return fail(ErrorCode::kInvalidArgument, who + ": triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v));
    const auto& tri = m.triangles[t];
    const double area = cross(m.vertices_mm[static_cast<size_t>(tri[1])] - m.vertices_mm[static_cast<size_t>(tri[0])],
                              m.vertices_mm[static_cast<size_t>(tri[2])] - m.vertices_mm[static_cast<size_t>(tri[0])]);
    if (area < 0)
      return fail(ErrorCode::kInvalidArgument, who + ": triangle " + std::to_string(t) + " is clockwise in the piece chart");
  }
  return {};
}

}  // namespace

Result<std::unique_ptr<GarmentSurface>> GarmentSurface::build(const Pattern& pattern, const Garment& garment) {
  if (garment.pieces.size() != pattern.pieces.size())
    return fail(ErrorCode::kInvalidArgument, "garment has " + std::to_string(garment.pieces.size()) +
                                                 " pieces, the pattern " + std::to_string(pattern.pieces.size()));
  auto s = std::unique_ptr<GarmentSurface>(new GarmentSurface());
  s->garment_ = garment;
  const size_t n3d = s->garment_.vertices_mm.size();
  s->charts_.resize(s->garment_.pieces.size());
  for (size_t i = 0; i < s->charts_.size(); ++i) {
    const GarmentPiece& gp = s->garment_.pieces[i];
    if (auto st = check_piece(pattern, static_cast<int>(i), gp, n3d); !st) return std::unexpected(st.error());
    PieceChart& c = s->charts_[i];
    c.piece = &gp;
    if (auto st = build_loop(pattern, static_cast<int>(i), c); !st) return std::unexpected(st.error());
    c.locator = PieceLocator(gp.mesh);
  }

  // Seam partners: boundary segments of different charts (or two legs of a dart) over the same
  // pair of 3D vertices are sewn together.
  std::map<std::pair<int, int>, std::vector<std::array<int, 2>>> by_edge;
  for (size_t p = 0; p < s->charts_.size(); ++p) {
    const PieceChart& c = s->charts_[p];
    for (size_t k = 0; k < c.segments.size(); ++k) {
      int va = c.piece->vertex_3d[static_cast<size_t>(c.segments[k].a)];
      int vb = c.piece->vertex_3d[static_cast<size_t>(c.segments[k].b)];
      if (va == vb) continue;
      by_edge[{std::min(va, vb), std::max(va, vb)}].push_back({static_cast<int>(p), static_cast<int>(k)});
    }
  }
  for (auto& [key, list] : by_edge) {
    if (list.size() < 2) continue;
    for (size_t i = 0; i < list.size(); ++i) {
      const auto [p, k] = list[i];
      const auto [q, m] = list[(i + 1) % list.size()];
      BoundarySegment& seg = s->charts_[static_cast<size_t>(p)].segments[static_cast<size_t>(k)];
      const BoundarySegment& other = s->charts_[static_cast<size_t>(q)].segments[static_cast<size_t>(m)];
      seg.partner_piece = q;
      seg.partner_segment = m;
      const int va = s->charts_[static_cast<size_t>(p)].piece->vertex_3d[static_cast<size_t>(seg.a)];
      const int oa = s->charts_[static_cast<size_t>(q)].piece->vertex_3d[static_cast<size_t>(other.a)];
      seg.partner_reversed = va != oa;
    }
  }

  // Orientation: pieces sewn along a reversed segment share a side; a same-direction seam flips
  // the partner. Breadth-first over the seam graph, then the whole garment faces away from its axis.
  const size_t np = s->charts_.size();
  std::vector<int> flip(np, 0);  // 0 unknown, +1 keep, -1 flip
  for (size_t start = 0; start < np; ++start) {
    if (flip[start] != 0) continue;
    flip[start] = 1;
    std::queue<size_t> todo;
    todo.push(start);
    while (!todo.empty()) {
      const size_t p = todo.front();
      todo.pop();
      for (const BoundarySegment& seg : s->charts_[p].segments) {
        if (seg.partner_piece < 0) continue;
        const size_t q = static_cast<size_t>(seg.partner_piece);
        if (flip[q] != 0) continue;
        flip[q] = seg.partner_reversed ? flip[p] : -flip[p];
        todo.push(q);
      }
    }
  }
  const auto& V = s->garment_.vertices_mm;
  Vec3 centroid;
  for (Vec3 v : V) centroid += v;
  if (!V.empty()) centroid = centroid / static_cast<double>(V.size());
  double outward = 0;
  for (size_t p = 0; p < np; ++p) {
    const GarmentPiece& gp = *s->charts_[p].piece;
    for (size_t t = 0; t < gp.mesh.triangles.size(); ++t) {
      std::array<int, 3> tri3;
      for (int k = 0; k < 3; ++k) tri3[static_cast<size_t>(k)] = gp.vertex_3d[static_cast<size_t>(gp.mesh.triangles[t][static_cast<size_t>(k)])];
      if (flip[p] < 0) std::swap(tri3[1], tri3[2]);
      const Vec3 a = V[static_cast<size_t>(tri3[0])], b = V[static_cast<size_t>(tri3[1])], c = V[static_cast<size_t>(tri3[2])];
      const Vec3 n = cross(b - a, c - a);
      // Radial direction from the vertical axis through the centroid (garment frame: y up).
      Vec3 radial = (a + b + c) / 3.0 - centroid;
      radial.y = 0;
      outward += dot(n, radial);
      s->triangles_3d_.push_back(tri3);
      s->owner_.push_back({static_cast<int>(p), static_cast<int>(t)});
    }
  }
  if (outward < 0)
    for (auto& t : s->triangles_3d_) std::swap(t[1], t[2]);
  s->normals_.assign(V.size(), Vec3{});
  for (const auto& t : s->triangles_3d_) {
    const Vec3 a = V[static_cast<size_t>(t[0])], b = V[static_cast<size_t>(t[1])], c = V[static_cast<size_t>(t[2])];
    const Vec3 n = cross(b - a, c - a);  // area weighted
    for (int v : t) s->normals_[static_cast<size_t>(v)] += n;
  }
  for (Vec3& n : s->normals_) n = normalized(n);
  return s;
}

SurfacePoint GarmentSurface::at(int piece, const ChartLocation& loc) const {
  const GarmentPiece& gp = *charts_[static_cast<size_t>(piece)].piece;
  const auto& tri = gp.mesh.triangles[static_cast<size_t>(loc.triangle)];
  SurfacePoint sp;
  Vec3 n;
  for (int k = 0; k < 3; ++k) {
    const size_t v3 = static_cast<size_t>(gp.vertex_3d[static_cast<size_t>(tri[static_cast<size_t>(k)])]);
    sp.position_mm += garment_.vertices_mm[v3] * loc.bary[static_cast<size_t>(k)];
    n += normals_[v3] * loc.bary[static_cast<size_t>(k)];
  }
  sp.normal = normalized(n);
  return sp;
}

Vec2 GarmentSurface::chart_position(int piece, const ChartLocation& loc) const {
  const GarmentPiece& gp = *charts_[static_cast<size_t>(piece)].piece;
  const auto& tri = gp.mesh.triangles[static_cast<size_t>(loc.triangle)];
  Vec2 p;
  for (int k = 0; k < 3; ++k) p += gp.mesh.vertices_mm[static_cast<size_t>(tri[static_cast<size_t>(k)])] * loc.bary[static_cast<size_t>(k)];
  return p;
}

}  // namespace tp::geometry::internal
