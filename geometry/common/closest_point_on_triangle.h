// geometry/common/closest_point_on_triangle.h: the point of a 3D triangle nearest to a point, with its weights and
// feature.
#pragma once

#include <array>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// The point of a triangle abc nearest to a query point.
struct TriangleClosestPoint {
  Vec3 point_mm;                 ///< the nearest point
  std::array<double, 3> bary{};  ///< its weights of a, b and c (each in [0, 1], summing to 1)
  /// The feature it lies on: 0 the face, 1..3 the edge ab, bc, ca (edge k runs from corner k - 1
  /// to corner k % 3), 4..6 the vertex a, b, c (vertex k is corner k - 4).
  int feature = 0;
};

/// Nearest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5: Voronoi
/// regions of the vertices, then the edges, then the face). A degenerate triangle (zero area)
/// whose face region is reached gives vertex a. Inline: the body SDF and the cloth's
/// self-collision call it in their innermost loops.
/// @param[in] p        query point (mm)
/// @param[in] a, b, c  triangle corners (mm)
[[nodiscard]] inline TriangleClosestPoint closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}, 4};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}, 5};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {a + ab * v, {1 - v, v, 0}, 1};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}, 6};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {a + ac * w, {1 - w, 0, w}, 3};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + (c - b) * w, {0, 1 - w, w}, 2};
  }
  const double sum = va + vb + vc;
  if (sum == 0) return {a, {1, 0, 0}, 4};
  const double denom = 1 / sum;
  const double v = vb * denom, w = vc * denom;
  return {a + ab * v + ac * w, {1 - v - w, v, w}, 0};
}

}  // namespace tp::geometry
