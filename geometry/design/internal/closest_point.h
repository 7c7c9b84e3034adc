// geometry/design/internal/closest_point.h: nearest point on a 3D triangle mesh (AABB tree).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// Where a query landed on the mesh.
struct MeshHit {
  int triangle = -1;
  std::array<double, 3> bary{};
  Vec3 point_mm;
  double distance_mm = 0;
};

/// Closest point queries on a fixed triangle soup. Thread-safe for queries after construction.
class ClosestPointIndex {
 public:
  ClosestPointIndex(const std::vector<Vec3>& vertices_mm, const std::vector<std::array<int, 3>>& triangles);
  ~ClosestPointIndex();
  ClosestPointIndex(const ClosestPointIndex&) = delete;
  ClosestPointIndex& operator=(const ClosestPointIndex&) = delete;

  /// The nearest surface point to `p` (triangle -1 for an empty mesh).
  MeshHit nearest(Vec3 p) const;

  /// Where the ray from `origin` along `direction` first meets the mesh (triangle -1: nowhere).
  MeshHit first_hit(Vec3 origin, Vec3 direction) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::geometry::internal
