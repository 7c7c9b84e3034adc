// geometry/pattern/import/freesewing_svg.h: importer for patterns exported by FreeSewing as SVG.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Notches are snapped onto the seam line when they lie this close (mm); farther ones are marks.
inline constexpr double kSvgNotchSnap_mm = 1.5;
/// A double notch (FreeSewing's "bnotch", the back notch) is cut as two slits this far apart (mm).
inline constexpr double kDoubleNotchSpacing_mm = 6;

/// Reads a FreeSewing SVG (units mm, y down): one piece per part group
/// ("fs-stack-<design>.<part>-part-<design>.<part>", named after <part>). The seam line is the
/// closed `fabric` path (not `fabric sa`, the cut line); other fabric paths become internal lines.
/// Edges split at corners (options.corner_angle_deg) and are named e0, e1, ... counter-clockwise
/// from the first corner after the path's start. Notches are `<use>` of #notch (slit) and
/// #bnotch (double slit) snapped to the nearest edge; marks inside the piece become drill marks
/// (diameter 0). The grain line and the cut-on-fold line come from the `note` paths with the
/// grainline/cutonfold markers; "cut N, mirrored, from <material>" from the part's annotation text.
/// Darts drawn into the seam line are detected (detect_darts). Cut-on-fold halves are unfolded and
/// quantities expanded per `options`. Coordinates are turned to y up.
/// The XML is parsed by pugixml: markup that is not well-formed (unquoted attributes, a stray '<',
/// unclosed elements) is kParse naming the file, line and byte; unknown entities are kept as written.
/// Errors name the file and line: kParse for XML or path data that does not parse; kInvalidPattern
/// when no part has a closed seam line.
[[nodiscard]] Result<Pattern> read_freesewing_svg(std::string_view text, const std::string& source_name,
                                                  const PatternImportOptions& options = {});

/// read_freesewing_svg on a file; kIo if it cannot be read.
[[nodiscard]] Result<Pattern> load_freesewing_svg(const std::filesystem::path& path,
                                                  const PatternImportOptions& options = {});

}  // namespace tp::geometry
