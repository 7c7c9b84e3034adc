// geometry/pattern/import/garmentcode.h: importer for GarmentCode pattern specifications (JSON).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Reads a GarmentCode specification ({"pattern": {"panels", "stitches", "panel_order"},
/// "properties": {"units_in_meter", "curvature_coords"}}): one piece per panel (in panel_order,
/// else by name), edges named "e<index>" as in the file, quadratic/cubic edges with control points
/// relative to the edge (or absolute per curvature_coords), circle arcs [radius, large_arc, right],
/// the 3D placement (R = Rz*Ry*Rx from "rotation" in degrees, then "translation") converted to mm
/// in the body frame (GarmentCode's frame already has y up, z to the front, x to the wearer's
/// left), and stitches (edge 1's end meets edge 2's start; "right_wrong" makes the starts meet).
/// Errors name the file and JSON pointer: kParse for a missing or mistyped field or an edge loop
/// that does not close; kUnknownReference for a stitch naming an unknown panel or edge index;
/// kInvalidPattern for an impossible circle (radius shorter than half the chord).
[[nodiscard]] Result<Pattern> read_garmentcode(std::string_view text, const std::string& source_name,
                                               const PatternImportOptions& options = {});

/// read_garmentcode on a file; kIo if it cannot be read.
[[nodiscard]] Result<Pattern> load_garmentcode(const std::filesystem::path& path,
                                               const PatternImportOptions& options = {});

}  // namespace tp::geometry
