// geometry/pattern/pattern_json.h: the project's native JSON pattern format (docs/pattern-format.md).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Parses a native pattern from `text`; `source_name` (usually the path) starts every message.
/// Curves are flattened, clockwise outlines reversed (warned) when options.fix_orientation,
/// cut-on-fold halves unfolded and quantities expanded per `options`, and stitches resolved to
/// physical pieces. Errors: kParse for syntax, a wrong type or a missing field, named by line:column
/// or JSON pointer ("tee.json: /pieces/1/edges/0/from: expected a point [x, y], found string");
/// kUnknownReference for a stitch, notch, dart or fold naming a piece or edge that does not exist;
/// kInvalidPattern for impossible geometry (arc through collinear points, crooked fold edge).
/// The result is not validated: call validate_pattern.
[[nodiscard]] Result<Pattern> read_pattern_json(std::string_view text, const std::string& source_name,
                                                const PatternImportOptions& options = {});

/// read_pattern_json on a file's contents; kIo if it cannot be read.
[[nodiscard]] Result<Pattern> load_pattern_json(const std::filesystem::path& path,
                                                const PatternImportOptions& options = {});

/// The pattern in the native format: units mm, one entry per physical piece (quantity 1, with
/// source_piece, mirrored, fold_line), curves as their definitions, stitches by piece and edge
/// name with numeric spans. Deterministic, so it can serve as a golden file; reading it back with
/// the same chord tolerance gives the same pattern.
std::string write_pattern_json(const Pattern& pattern);

/// write_pattern_json to a file; kIo on failure.
[[nodiscard]] Status save_pattern_json(const Pattern& pattern, const std::filesystem::path& path);

}  // namespace tp::geometry
