// geometry/design/transfer_surface_points.cpp: nearest point on one garment -> piece position ->
// the other garment's point there.
#include "geometry/design/transfer_surface_points.h"

#include "geometry/common/closest_point_on_triangle.h"
#include "geometry/design/internal/closest_point.h"
#include "geometry/design/internal/garment_surface.h"

namespace tp::geometry {

using namespace internal;

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
    const ChartLocation loc{tri, closest_point_on_triangle(hit.point_mm, corner[0], corner[1], corner[2]).bary};
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
