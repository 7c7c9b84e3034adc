// geometry/pattern/orient.h: making piece outlines counter-clockwise without breaking references.
#pragma once

#include <string>
#include <vector>

#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Runs a piece's outline the other way round: edge i becomes edge n-1-i, each edge reversed;
/// notch positions, dart legs and the fold edge follow. Stitches are not touched (see below).
void reverse_outline(Piece& piece);

/// Reverses every piece whose outline is clockwise (negative area) and updates the stitches on
/// it: spans are mirrored along their edge and the stitch orientation flips. Returns the names of
/// the reversed pieces (importers put them in Pattern::warnings).
std::vector<std::string> orient_counter_clockwise(Pattern& pattern);

}  // namespace tp::geometry
