// geometry/cutfile/dxf_aama_writer.h: writes a cut job as a DXF-AAMA (ASTM D6673) file.
#pragma once

#include <filesystem>
#include <string>

#include "geometry/common/error.h"
#include "geometry/cutfile/cut_job.h"

namespace tp::geometry {

/// DXF R12 text in mm ($INSUNITS 4, "Units: METRIC"): one BLOCK per placed piece holding, in
/// piece mm, the cut line (layer 1, V/U notches cut in, closed POLYLINE), notch slits (layer 4,
/// LINE from the cut line inwards), grain line (7, LINE), internal lines (8), drill holes (13,
/// POINT, or CIRCLE when punched), sew line (14, closed POLYLINE), label strokes (15) and the
/// AAMA annotation text ("Piece Name:", "Size:", "Quantity:"...) on layer 1; then one INSERT
/// per piece with its placement (mirror as x scale -1, rotation, offset), so the file opens
/// positioned as printed on the roll. Block names are the piece names made DXF-safe.
std::string dxf_aama_text(const CutJob& job);

/// Writes dxf_aama_text to `path`; kIo naming the file on failure.
[[nodiscard]] Status write_dxf_aama(const CutJob& job, const std::filesystem::path& path);

}  // namespace tp::geometry
