// geometry/pattern/import/obj_garment.h: importer for a 3D garment OBJ whose texture coordinates are its pieces in mm.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// The pattern and the 3D garment read from one OBJ.
struct ObjGarment {
  Pattern pattern;
  Garment garment;
};

/// Reads an OBJ garment: every face has texture coordinates, which are the flat pieces in mm
/// (one UV island per piece, islands connected through shared texture-coordinate edges), and its
/// positions are the sewn garment (options.obj_position_unit_mm mm per unit). For each island:
/// the piece outline is the island's boundary (a polyline, counter-clockwise), split into edges
/// where the neighbouring island changes and at corners (options.corner_angle_deg, applied on both
/// sides of a seam so stitched edges match); edges shared in 3D by two islands become stitches.
/// The piece is named after the OBJ group or object its faces belong to ("g"/"o"), else
/// "piece<N>". The garment has one 3D vertex per OBJ position and per piece the island's mesh
/// (texture coordinates as piece mm, faces fan-triangulated) with its 3D vertex indices, so each
/// seam vertex is a single 3D vertex with one texture coordinate per piece (DESIGN.md decision 2).
/// Errors name the file and line or the island: kParse for malformed lines, indices out of range
/// or faces without texture coordinates; kInvalidPattern for an island whose texture coordinates
/// are flipped (mirrored) or folded, that has holes or a non-manifold boundary, for a texture
/// vertex used with two positions, and for a 3D edge shared by more than two faces.
[[nodiscard]] Result<ObjGarment> read_obj_garment(std::string_view text, const std::string& source_name,
                                                  const PatternImportOptions& options = {});

/// read_obj_garment on a file; kIo if it cannot be read.
[[nodiscard]] Result<ObjGarment> load_obj_garment(const std::filesystem::path& path, const PatternImportOptions& options = {});

}  // namespace tp::geometry
