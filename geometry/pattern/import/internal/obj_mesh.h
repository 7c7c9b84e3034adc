// geometry/pattern/import/internal/obj_mesh.h: the parts of a Wavefront OBJ the garment importer reads.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// A face corner: 0-based position and texture-coordinate indices.
struct ObjCorner {
  int v = 0;
  int vt = 0;
};

/// A triangle of a (fan-triangulated) face, with the group it was in and its line.
struct ObjTriangle {
  std::array<ObjCorner, 3> c;
  int group = -1;
  int line = 0;
};

struct ObjMesh {
  std::vector<Vec3> positions;
  std::vector<Vec2> uvs;
  std::vector<ObjTriangle> triangles;
  std::vector<std::string> groups;  ///< names from "g" and "o" lines, indexed by ObjTriangle::group
};

/// Parses v, vt, f (v/vt or v/vt/vn corners, negative indices relative), g and o; other lines are
/// skipped. Fails (kParse, "file:line: ...") on a malformed number, an index out of range, or a
/// face with fewer than 3 corners or without texture coordinates.
[[nodiscard]] Result<ObjMesh> parse_obj(std::string_view text, const std::string& file);

}  // namespace tp::geometry::internal
