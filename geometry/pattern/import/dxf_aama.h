// geometry/pattern/import/dxf_aama.h: importer for DXF-AAMA / ASTM D6673 cutting-room pattern files.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Notches on the cut line are moved to the seam line when it lies within this distance (mm),
/// which covers any seam allowance; notches on a boundary that is itself the seam line snap
/// within kDxfNotchSnap_mm.
inline constexpr double kDxfNotchToSewLine_mm = 40;
inline constexpr double kDxfNotchSnap_mm = 2;

/// Reads a DXF-AAMA file: one piece per BLOCK (blocks named "*..." are skipped) holding a
/// boundary on layer 1. Layers: 1 boundary (cut line), 2 turn points (corners), 3 curve points,
/// 4 notches (POINT, or a LINE whose end on the outline is the notch), 6 mirror line (cut on
/// fold), 7 grain line, 8 internal lines, 11 internal cut-outs (as internal lines), 13 drill holes
/// (POINT, or CIRCLE giving the diameter), 14 sew line, 15 annotation. When a sew line is present
/// it is the piece outline (the model's outline is the seam line) and the boundary is the cut
/// line; notches on the cut line are projected onto the seam line. Geometry may be POLYLINE
/// (with bulges), LWPOLYLINE, LINE chains and ARC. Edges split at turn points when the outline
/// is the boundary and has them, else at corners by angle; darts are detected. Text
/// "Piece Name:", "Quantity:", "Material:", "Size:", "Category:", "Mirror: Y" (anywhere in the
/// block) name the piece and its copies (the block name is the fallback name); "Units: METRIC|
/// ENGLISH" text, else $INSUNITS or $MEASUREMENT in the header, else options.dxf_default_unit_mm
/// give the units. Errors name the file and line: kParse for malformed group codes; kInvalidPattern
/// for a block whose outline does not close or a file without any piece.
[[nodiscard]] Result<Pattern> read_dxf_aama(std::string_view text, const std::string& source_name,
                                            const PatternImportOptions& options = {});

/// read_dxf_aama on a file; kIo if it cannot be read.
[[nodiscard]] Result<Pattern> load_dxf_aama(const std::filesystem::path& path, const PatternImportOptions& options = {});

}  // namespace tp::geometry
