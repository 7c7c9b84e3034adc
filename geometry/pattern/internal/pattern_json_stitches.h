// geometry/pattern/internal/pattern_json_stitches.h: the "stitches" array of the native format.
#pragma once

#include <map>
#include <string>

#include "geometry/pattern/internal/json_fields.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::internal {

/// Reads root["stitches"] into pattern.stitches, resolving piece names to physical pieces (a
/// drafted name expands to its copies) and edges of unfolded pieces to both halves.
/// `unfolded` maps each physical piece name to whether it was unfolded from a half.
[[nodiscard]] Status read_pattern_json_stitches(const nlohmann::json& root, const JsonPath& at, double scale,
                                                const std::map<std::string, bool>& unfolded, Pattern& pattern);

}  // namespace tp::geometry::internal
