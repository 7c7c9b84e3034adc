// geometry/mesh/read_obj.h: the one Wavefront OBJ reader (positions, texture coordinates, faces, groups).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"

namespace tp::geometry {

/// A face corner: 0-based position index and texture-coordinate index (-1 when the corner has none).
struct ObjCorner {
  int v = 0;
  int vt = -1;
};

/// A triangle of a (fan-triangulated) face, with the group it was in (-1 before any) and its line.
struct ObjTriangle {
  std::array<ObjCorner, 3> c;
  int group = -1;
  int line = 0;
};

/// An OBJ file in the units it was saved in.
struct ObjMesh {
  std::vector<Vec3> positions;         ///< #V `v` positions
  std::vector<Vec2> uvs;               ///< #T `vt` coordinates
  std::vector<ObjTriangle> triangles;  ///< #F triangles, indices into positions and uvs
  std::vector<std::string> groups;     ///< names from "g" and "o" lines, indexed by ObjTriangle::group
};

struct ObjReadOptions {
  /// Every face corner must name a texture coordinate (v/vt or v/vt/vn); a corner without one fails.
  bool require_texture_coordinates = false;
};

/// Parses v, vt, f (v, v/vt, v/vt/vn or v//vn corners; 1-based, negative indices count back from the
/// latest; polygons are fanned from their first corner), g and o; other lines (vn, usemtl, ...) are
/// skipped. `file` names the source in errors. Fails with kParse, "file:line: ...", on a malformed
/// number, an index out of range, a face with fewer than 3 corners, or (if required) a corner without
/// a texture coordinate. A file without faces is not an error here: the caller says what it needs.
[[nodiscard]] Result<ObjMesh> read_obj(std::string_view text, const std::string& file,
                                       const ObjReadOptions& options = {});

}  // namespace tp::geometry
