// geometry/mesh/sample_boundary.h: seam-aware sampling of piece outlines before meshing.
#pragma once

#include <array>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// The sampled seam line of one piece: a closed ring of points and where each edge lies on it.
struct PieceBoundary {
  std::vector<Vec2> ring_mm;                  ///< closed ring in outline order, no repeat, mm
  std::vector<std::vector<int>> edge_vertices;  ///< per edge: ring indices start..end inclusive
};

/// Sampled outlines of every piece, and the matched ring vertices of every stitch.
struct BoundarySampling {
  std::vector<PieceBoundary> pieces;  ///< same order as Pattern::pieces
  /// Per stitch: pairs {ring index on piece a, ring index on piece b} that are sewn together,
  /// from span a's start to its end.
  std::vector<std::vector<std::array<int, 2>>> stitch_pairs;
};

/// Samples every edge of every piece at arc-length steps of at most `target_edge_mm`, so that
/// the two spans of each stitch get the same number of vertices at matching arc-length
/// fractions (spans sewn to several others share one count). Corners between edges are kept.
/// Fails (kInvalidPattern / kUnknownReference / kMeshing) on a zero-length edge, a stitch that
/// names a missing piece or edge, a span outside its edge, or overlapping spans on one edge;
/// messages name the piece, the edge and the stitch.
[[nodiscard]] Result<BoundarySampling> sample_boundary(const Pattern& pattern, double target_edge_mm);

/// Point at arc length `s_mm` along a polyline (clamped to its ends).
Vec2 point_at_arc_length(const std::vector<Vec2>& polyline_mm, double s_mm);

}  // namespace tp::geometry
