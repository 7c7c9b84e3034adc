// geometry/design/transfer_surface_points.cpp: nearest point on one garment -> piece position ->
// the other garment's point there.
#include "geometry/design/transfer_surface_points.h"

#include "geometry/design/internal/closest_point.h"
#include "geometry/design/internal/garment_surface.h"

namespace tp::geometry {

using namespace internal;

namespace {

// Barycentric weights of the point of triangle abc nearest to p (p assumed on or near its plane).
std::array<double, 3> barycentric_3d(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 v0 = b - a, v1 = c - a, v2 = p - a;
  const double d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1), d20 = dot(v2, v0), d21 = dot(v2, v1);
  const double den = d00 * d11 - d01 * d01;
  if (den == 0) return {1, 0, 0};
  const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
  return {1 - v - w, v, w};
}

}  // namespace

Result<std::vector<PiecePoint>> locate_on_pieces(const Pattern& pattern, const Garment& garment,
                                                 const std::vector<Vec3>& points_mm) {
  auto surface = GarmentSurface::build(pattern, garment);
  if (!surface) return std::unexpected(surface.error().with_context("garment the points are on"));
  const GarmentSurface& S = **surface;
  const ClosestPointIndex index(S.garment().vertices_mm, S.triangles_3d());
  std::vector<PiecePoint> out;
  out.reserve(points_mm.size());
  for (const Vec3& p : points_mm) {
    const MeshHit hit = index.nearest(p);
    if (hit.triangle < 0) return fail(ErrorCode::kInvalidArgument, "garment the points are on: no triangles");
    const auto [chart, tri] = S.triangle_owner()[static_cast<size_t>(hit.triangle)];
    // The hit in the piece triangle's own corner order, then its place on the piece.
    std::array<Vec3, 3> corner;
    for (int k = 0; k < 3; ++k) {
      ChartLocation at{tri, {0, 0, 0}};
      at.bary[static_cast<size_t>(k)] = 1;
      corner[static_cast<size_t>(k)] = S.at(chart, at).position_mm;
    }
    const ChartLocation loc{tri, barycentric_3d(hit.point_mm, corner[0], corner[1], corner[2])};
    out.push_back({S.chart(chart).piece->piece, S.chart_position(chart, loc), p - hit.point_mm});
  }
  return out;
}

Result<std::vector<GarmentPoint>> place_on_garment(const Pattern& pattern, const Garment& garment,
                                                   const std::vector<PiecePoint>& points) {
  auto surface = GarmentSurface::build(pattern, garment);
  if (!surface) return std::unexpected(surface.error().with_context("garment the points go to"));
  const GarmentSurface& T = **surface;
  std::vector<GarmentPoint> out;
  out.reserve(points.size());
  for (const PiecePoint& pp : points) {
    int chart = -1;
    for (int c = 0; c < T.piece_count() && chart < 0; ++c)
      if (T.chart(c).piece->piece == pp.piece) chart = c;
    if (chart < 0)
      return fail(ErrorCode::kInvalidArgument,
                  "garment the points go to: piece " + std::to_string(pp.piece) + " is not on the garment");
    const ChartLocation loc = T.chart(chart).locator.nearest(pp.position_mm);
    out.push_back({T.at(chart, loc).position_mm, norm(T.chart_position(chart, loc) - pp.position_mm)});
  }
  return out;
}

Result<std::vector<Vec3>> transfer_surface_points(const Pattern& pattern, const Garment& from, const Garment& to,
                                                  const std::vector<Vec3>& points_mm) {
  auto located = locate_on_pieces(pattern, from, points_mm);
  if (!located) return std::unexpected(located.error());
  auto placed = place_on_garment(pattern, to, *located);
  if (!placed) return std::unexpected(placed.error());
  std::vector<Vec3> out;
  out.reserve(placed->size());
  for (const GarmentPoint& g : *placed) out.push_back(g.position_mm);
  return out;
}

}  // namespace tp::geometry
