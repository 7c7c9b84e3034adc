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

Result<std::vector<Vec3>> transfer_surface_points(const Pattern& pattern, const Garment& from, const Garment& to,
                                                  const std::vector<Vec3>& points_mm) {
  auto source = GarmentSurface::build(pattern, from);
  if (!source) return std::unexpected(source.error().with_context("garment the points are on"));
  auto target = GarmentSurface::build(pattern, to);
  if (!target) return std::unexpected(target.error().with_context("garment the points go to"));
  const GarmentSurface& S = **source;
  const GarmentSurface& T = **target;
  const ClosestPointIndex index(S.garment().vertices_mm, S.triangles_3d());
  std::vector<Vec3> out;
  out.reserve(points_mm.size());
  for (const Vec3& p : points_mm) {
    const MeshHit hit = index.nearest(p);
    if (hit.triangle < 0) return fail(ErrorCode::kInvalidArgument, "garment the points are on: no triangles");
    const auto [piece, tri] = S.triangle_owner()[static_cast<size_t>(hit.triangle)];
    // The hit in the piece triangle's own corner order, then its place on the piece.
    std::array<Vec3, 3> corner;
    for (int k = 0; k < 3; ++k) {
      ChartLocation at{tri, {0, 0, 0}};
      at.bary[static_cast<size_t>(k)] = 1;
      corner[static_cast<size_t>(k)] = S.at(piece, at).position_mm;
    }
    ChartLocation loc{tri, barycentric_3d(hit.point_mm, corner[0], corner[1], corner[2])};
    const Vec2 on_piece = S.chart_position(piece, loc);
    out.push_back(T.at(piece, T.chart(piece).locator.nearest(on_piece)).position_mm);
  }
  return out;
}

}  // namespace tp::geometry
