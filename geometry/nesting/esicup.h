// geometry/nesting/esicup.h: reading ESICUP strip-packing instances (the JSON form used by
// sparrow and jagua-rs) into a StripProblem for benchmarks.
#pragma once

#include <filesystem>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/nesting/strip_nester.h"

namespace tp::geometry {

/// Parses an instance: `name`, `strip_height` (the fixed strip width), and `items`, each with
/// `id`, `demand`, optional `allowed_orientations` (degrees; absent means 0 only) and `shape`
/// (`simple_polygon` data [[x, y], ...], `rectangle` {x_min, y_min, width, height}, or `polygon`
/// {outer, inner}, whose holes are ignored: pieces are not nested inside holes).
/// Fails with kParse naming `source` and the JSON pointer of the offending field.
[[nodiscard]] Result<StripProblem> parse_esicup(std::string_view json_text, std::string_view source);

/// Reads and parses an instance file; kIo when it cannot be read.
[[nodiscard]] Result<StripProblem> load_esicup(const std::filesystem::path& file);

}  // namespace tp::geometry
