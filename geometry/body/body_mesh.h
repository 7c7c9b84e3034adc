// geometry/body/body_mesh.h: a body (dress form or scanned body) as a closed triangle mesh in mm.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// A closed, outward-oriented triangle mesh in the body frame: millimetres, y up (feet at
/// y = 0), z towards the front, x towards the wearer's left.
struct BodyMesh {
  std::string name;                           ///< "dress_form" or the file it came from
  std::vector<Vec3> vertices_mm;              ///< #V positions
  std::vector<std::array<int, 3>> triangles;  ///< #F vertex indices, counter-clockwise seen from outside
};

/// Axis-aligned bounds of the body's vertices.
struct Box3 {
  Vec3 min{1e300, 1e300, 1e300}, max{-1e300, -1e300, -1e300};
  void add(Vec3 p) {
    min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y), std::fmin(min.z, p.z)};
    max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y), std::fmax(max.z, p.z)};
  }
};

inline Box3 bounds(const BodyMesh& body) {
  Box3 b;
  for (const Vec3& p : body.vertices_mm) b.add(p);
  return b;
}

}  // namespace tp::geometry
