// geometry/pattern/stitches_json.h: a stitches file: suggested (or hand-made) stitches for a pattern, in the native format.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"
#include "geometry/pattern/suggest_stitches.h"

namespace tp::geometry {

/// The suggestions as a stitches file (docs/pattern-format.md, "Stitches files"):
/// {"format": "tp-stitches", "version": 1, "pattern": name, "units": "mm", "stitches": [...]}, each
/// stitch as in the native pattern format (physical piece and edge names, spans in mm) plus
/// "score" and "reason" for the operator. Deterministic.
std::string write_stitches_json(const Pattern& pattern, const std::vector<StitchSuggestion>& suggestions);

/// Reads a stitches file against `pattern` (whose physical piece and edge names it uses; a
/// drafted piece's name stands for all its copies). Errors name the file and the JSON pointer:
/// kParse for syntax or a wrong type, kUnknownReference for a piece, edge or notch the pattern
/// does not have. The stitches are not validated: append them and call validate_pattern.
[[nodiscard]] Result<std::vector<Stitch>> read_stitches_json(std::string_view text, const std::string& source_name,
                                                             const Pattern& pattern);

/// read_stitches_json on a file's contents; kIo if it cannot be read.
[[nodiscard]] Result<std::vector<Stitch>> load_stitches_json(const std::filesystem::path& path, const Pattern& pattern);

}  // namespace tp::geometry
