// geometry/pattern/internal/free_edge_chains.h: the runs of unstitched edges a pattern's seams leave (waists,
// necklines).
#pragma once

#include <vector>

#include "geometry/pattern/pattern.h"

namespace tp::geometry::internal {

/// One edge of one piece.
struct EdgeRef {
  int piece = 0, edge = 0;
  bool operator==(const EdgeRef&) const = default;
};

/// Free edges in the order they follow each other once `stitches` are sewn (right sides
/// together: a's start meets b's end, as in pattern.h), each one's end meeting the next one's
/// start: a skirt's waist runs across the darts and side seams. `closed` when the last edge
/// runs into the first. A stitch on part of an edge ends a chain there.
struct FreeEdgeChain {
  std::vector<EdgeRef> edges;
  bool closed = false;
};

/// Every chain of free edges of `pattern` under `stitches` (pattern.stitches are not read), in
/// the order of their first edge; every free edge is in exactly one chain.
[[nodiscard]] std::vector<FreeEdgeChain> free_edge_chains(const Pattern& pattern, const std::vector<Stitch>& stitches);

}  // namespace tp::geometry::internal
