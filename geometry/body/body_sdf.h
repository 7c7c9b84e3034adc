// geometry/body/body_sdf.h: the body as a collision object: fast signed distance and closest point.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/body/body_mesh.h"
#include "geometry/common/error.h"

namespace tp::geometry {

/// Signed distance to a closed body mesh, answered near-exactly within a band around the
/// surface. A grid stores, per node, the nearest triangle (exact within `band_cells` cells of
/// the surface) and whether the node is inside (winding number along z rays, so overlapping
/// closed parts count as their union). A query starts from the nearest triangles of its cell's
/// eight nodes, walks to neighbouring triangles while they are nearer (so the nearest feature is
/// found, not a neighbour's), and signs the distance with angle-weighted pseudo-normals.
class BodySdf {
 public:
  /// Result of a query. distance_mm < 0 inside the body.
  struct Hit {
    double distance_mm = 0;
    Vec3 closest_mm;   ///< nearest surface point (valid when near)
    Vec3 normal;       ///< unit outward direction at the nearest point (valid when near)
    bool near = false; ///< within the exact band; otherwise distance is only a bound (|d| >= band)
  };

  /// Builds the grid for `body` (moved in). `spacing_mm` is the grid step, `band_cells` the
  /// exact band's half width in cells. Fails with kInvalidArgument on an empty mesh or a bad
  /// spacing; kInvalidArgument if the grid would exceed 64 M nodes.
  [[nodiscard]] static Result<BodySdf> build(BodyMesh body, double spacing_mm = 8, int band_cells = 2);

  /// Signed distance, nearest point and outward normal at `p_mm`. Thread-safe.
  Hit query(Vec3 p_mm) const;

  /// Signed distance interpolated from the grid (trilinear): cheap, within about one grid
  /// step of the truth near the surface, +-band_mm() away from it. For culling only.
  double approx_distance_mm(Vec3 p_mm) const;

  /// Exact band half width in mm: queries closer than this to the surface are near.
  double band_mm() const { return band_cells_ * spacing_mm_; }
  double spacing_mm() const { return spacing_mm_; }
  const BodyMesh& mesh() const { return mesh_; }
  const Box3& box() const { return box_; }

 private:
  size_t node(int i, int j, int k) const { return (static_cast<size_t>(k) * ny_ + j) * nx_ + i; }

  BodyMesh mesh_;
  Box3 box_;
  std::vector<Vec3> face_normal_;                  ///< unit, per triangle (zero if degenerate)
  std::vector<Vec3> vertex_normal_;                ///< angle-weighted pseudo-normals
  std::vector<std::array<Vec3, 3>> edge_normal_;   ///< per triangle edge k = (v_k, v_k+1)
  Vec3 origin_mm_;
  double spacing_mm_ = 8;
  int band_cells_ = 2;
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<int32_t> vertex_face_start_;  ///< CSR: faces around vertex v are
  std::vector<int32_t> vertex_faces_;       ///< vertex_faces_[start[v] .. start[v+1])
  std::vector<uint8_t> degenerate_;         ///< zero-area triangles, never answered
  std::vector<int32_t> node_triangle_;  ///< nearest triangle within the band, else -1
  std::vector<float> node_distance_;    ///< signed distance at the node (+-band when far)
  std::vector<uint8_t> node_inside_;
};

}  // namespace tp::geometry
