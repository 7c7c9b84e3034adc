// geometry/cutfile/dxf_aama_writer.h: writes a cut job as a DXF-AAMA (ASTM D6673) file.
#pragma once

#include <filesystem>
#include <string>

#include "geometry/common/error.h"
#include "geometry/cutfile/cut_job.h"

namespace tp::geometry {

/// DXF R12 (AC1009) text in mm: no R2000 header variables; units as AAMA "Units: METRIC" text,
/// $EXTMIN/$EXTMAX the roll; LTYPE (CONTINUOUS), LAYER and STYLE tables. One BLOCK per placed
/// piece holding, in piece mm, the cut line (layer 1, V/U notches cut in, closed POLYLINE),
/// notch slits (layer 4, LINE from the cut line inwards), grain line (7, LINE), internal lines
/// (8), drill holes (13, POINT), sew line (14, closed POLYLINE), label strokes (15) and the AAMA
/// annotation text ("Piece Name:", "Size:", "Quantity:"...) on layer 1, sized to stay inside the
/// piece; then the Style System Text (TEXT on layer 1 in the roll's leading-edge corner) and one
/// INSERT per piece placing it in the cutter's frame (roll_to_cutter: x scale -1 where the
/// placement mirrors, rotation, position), so the file opens as the pieces lie on the printed
/// roll, face up. Block names are the piece names made DXF-safe.
std::string dxf_aama_text(const CutJob& job);

/// Writes dxf_aama_text to `path`; kIo naming the file on failure.
[[nodiscard]] Status write_dxf_aama(const CutJob& job, const std::filesystem::path& path);

}  // namespace tp::geometry
