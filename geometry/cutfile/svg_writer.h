// geometry/cutfile/svg_writer.h: writes a cut job as an SVG drawing of the marker, in mm.
#pragma once

#include <filesystem>
#include <string>

#include "geometry/common/error.h"
#include "geometry/cutfile/cut_job.h"

namespace tp::geometry {

/// SVG 1.1 in mm (viewBox in mm, 1 user unit = 1 mm): the roll as wide as the fabric and as long
/// as the marker (x across, y down the roll in feed direction), one group per placed piece with
/// its cut line (class "cut"), notches ("notch"), grain line ("grain"), drill holes ("drill"),
/// sew line ("sew"), internal lines ("internal"), label strokes ("mark") and its name.
std::string svg_text(const CutJob& job);

/// Writes svg_text to `path`; kIo naming the file on failure.
[[nodiscard]] Status write_svg(const CutJob& job, const std::filesystem::path& path);

}  // namespace tp::geometry
