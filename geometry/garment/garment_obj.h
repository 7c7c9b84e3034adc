// geometry/garment/garment_obj.h: the 3D garment as Wavefront OBJ text with per-piece texture coordinates.
#pragma once

#include <string>

#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// OBJ text of `garment`: `v` are the shared 3D vertices in mm (body frame); each piece is a
/// group `g <piece name>` whose `vt` are its 2D mesh coordinates in mm plus a per-piece offset
/// that lays the pieces side by side without overlap (the offsets are written as comments
/// `# piece <name> uv_offset_mm <dx> <dy>`), and whose faces `f v/vt` use them. A seam vertex is
/// one `v` with one `vt` per joining piece (the paper's section 3.4).
std::string garment_to_obj(const Pattern& pattern, const Garment& garment);

}  // namespace tp::geometry
