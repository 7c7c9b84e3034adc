// geometry/body/load_body_obj.h: read a body mesh (Wavefront OBJ) in the units it was saved in.
#pragma once

#include <string>
#include <string_view>

#include "geometry/body/body_mesh.h"
#include "geometry/common/error.h"

namespace tp::geometry {

/// Parses OBJ text: `v x y z` and `f` lines (v, v/vt, v/vt/vn, v//vn; polygons are fanned;
/// negative indices count back). Positions are multiplied by `mm_per_unit` (1000 for metres,
/// 10 for cm, 1 for mm). `source` names the file in errors. Fails with kParse naming the line
/// on a malformed number, an index out of range, or a file without triangles.
[[nodiscard]] Result<BodyMesh> parse_body_obj(std::string_view text, double mm_per_unit, const std::string& source);

/// Reads and parses an OBJ file (see parse_body_obj); kIo if it cannot be read.
[[nodiscard]] Result<BodyMesh> load_body_obj(const std::string& path, double mm_per_unit);

}  // namespace tp::geometry
