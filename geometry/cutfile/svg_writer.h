// geometry/cutfile/svg_writer.h: writes a cut job as an SVG drawing of the marker, in mm.
#pragma once

#include <filesystem>
#include <string>

#include "geometry/common/error.h"
#include "geometry/cutfile/cut_job.h"

namespace tp::geometry {

/// SVG 1.1 in mm (viewBox in mm, 1 user unit = 1 mm) in the roll frame seen from the printed face
/// (x across from the left selvedge, y down the roll from the leading edge; docs/roll-frame.md).
/// One group per cutter layer, ids a cutter's import selects by (also Inkscape layers):
/// `roll` (the roll rectangle), `cut` (each piece's cut line, id "cut-<piece>"), `sew`, `notch`,
/// `drill`, `grain`, `internal` and `annotation` (label strokes and piece names); every element
/// names its piece in `data-piece`.
std::string svg_text(const CutJob& job);

/// Writes svg_text to `path`; kIo naming the file on failure.
[[nodiscard]] Status write_svg(const CutJob& job, const std::filesystem::path& path);

}  // namespace tp::geometry
