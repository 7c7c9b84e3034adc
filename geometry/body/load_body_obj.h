// geometry/body/load_body_obj.h: read a body mesh (Wavefront OBJ) in the units it was saved in.
#pragma once

#include <string>
#include <string_view>

#include "geometry/body/body_mesh.h"
#include "geometry/common/error.h"

namespace tp::geometry {

/// Parses OBJ text with read_obj (geometry/mesh/read_obj.h: v/vt/vn corners, polygons fanned,
/// negative indices count back) and keeps positions and triangles. Positions are multiplied by `mm_per_unit` (1000 for
/// metres, 10 for cm, 1 for mm). `source` names the file in errors. Fails with kParse naming the file and line on a
/// malformed number or an index out of range, and naming the file if it has no triangles.
[[nodiscard]] Result<BodyMesh> parse_body_obj(std::string_view text, double mm_per_unit, const std::string& source);

/// Reads and parses an OBJ file (see parse_body_obj); kIo if it cannot be read.
[[nodiscard]] Result<BodyMesh> load_body_obj(const std::string& path, double mm_per_unit);

}  // namespace tp::geometry
