// geometry/pattern/pattern.h: the sewing-pattern model: pieces, edges, notches, grain, stitches.
//
// Units are millimetres in each piece's own 2D frame (x right, y up). A piece outline is the
// seam line (not the cut line): allowance is added later (geometry/allowance).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/common/vec.h"

namespace tp::geometry {

/// How an edge was drawn; the polyline is always filled, the curve kept for cut files.
enum class EdgeCurve { kLine, kQuadratic, kCubic, kArc, kPolyline };

/// One edge of a piece outline, from its start vertex to the next edge's start vertex.
///
/// `control_mm` keeps the curve definition (cut files and exact lengths need it); the end points
/// are not repeated there, they are points_mm.front() and points_mm.back():
///  - kLine, kPolyline: empty (a polyline is defined by points_mm itself);
///  - kQuadratic: a chain of n quadratic Beziers, c1, j1, c2, j2, ..., cn (2n-1 points, j = joints);
///  - kCubic: a chain of n cubic Beziers, c1a, c1b, j1, c2a, c2b, j2, ..., cna, cnb (3n-1 points);
///  - kArc: {centre, a point on the arc strictly between the ends} (a circular arc under 360 deg).
/// points_mm is the curve flattened at a chord tolerance (geometry/pattern/curve.h).
struct Edge {
  std::string name;                 ///< unique within the piece ("side_seam", "hem")
  EdgeCurve curve = EdgeCurve::kLine;
  std::vector<Vec2> control_mm;     ///< curve definition by `curve` (see above)
  std::vector<Vec2> points_mm;      ///< flattened polyline, start..end inclusive, >= 2 points
};

/// Notch shapes a cutter knows.
enum class NotchType { kSlit, kV, kT, kU };

/// A notch on an edge, at an arc length measured from the edge's start.
struct Notch {
  std::string name;
  int edge = 0;
  double position_mm = 0;
  NotchType type = NotchType::kSlit;
};

/// Grain line: fabric warp direction within the piece, from `from_mm` to `to_mm`.
struct GrainLine {
  Vec2 from_mm, to_mm;
};

/// A line drawn inside the piece (placement line, pocket position, fold guide).
struct InternalLine {
  std::string name;
  std::vector<Vec2> points_mm;
};

/// A dart: its two legs are outline edges sewn to each other (a stitch also says so).
struct Dart {
  std::string name;
  int leg_a = 0;  ///< edge index of the first leg
  int leg_b = 0;  ///< edge index of the second leg
};

/// A drill hole (pocket corner, dart tip marker). Diameter 0 marks the point without punching it.
struct DrillHole {
  Vec2 position_mm;
  double diameter_mm = 3;
};

/// Where the piece sits around the body before sewing: p3d = rotation * (x, y, 0) + translation.
struct Placement3d {
  std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< row-major 3x3
  Vec3 translation_mm;
};

/// One physical piece of fabric to cut (a "cut 2" pattern piece appears as two pieces).
struct Piece {
  std::string name;                     ///< unique within the pattern
  std::vector<Edge> edges;              ///< closed outline, counter-clockwise
  std::vector<Notch> notches;
  std::optional<GrainLine> grain;
  std::optional<int> fold_edge;         ///< edge on the fold of a half piece kept folded (cut on fold)
  std::vector<InternalLine> internal_lines;
  std::vector<Dart> darts;
  std::vector<DrillHole> drill_holes;
  std::string role;                     ///< "front", "back", "sleeve", "waistband", ... for placement
  std::string source_piece;             ///< pattern piece it was cut from ("sleeve" for "sleeve_l")
  bool mirrored = false;                ///< the mirrored copy of a left/right pair
  std::optional<Placement3d> placement;
  /// Mirror line of a piece unfolded from a cut-on-fold half (the fold), from..to in piece mm.
  std::optional<std::array<Vec2, 2>> fold_line_mm;
  std::string material;                 ///< "fabric", "lining", ... as the source names it; may be empty
};

/// A span of one edge: [from_mm, to_mm] in arc length from the edge start; to_mm < 0 means the end.
struct EdgeSpan {
  int piece = 0;
  int edge = 0;
  double from_mm = 0;
  double to_mm = -1;
};

/// Two spans sewn together. Right sides together, `a` start meets `b` end unless `same_direction`.
struct Stitch {
  EdgeSpan a, b;
  bool same_direction = false;
  /// Eased or gathered seam: the longer side may be up to this many times the shorter, and is
  /// distributed along it (the excess becomes folds). 0: an ordinary seam, both sides equal.
  double ease_ratio = 0;
};

/// A sewing pattern for one garment in one size.
struct Pattern {
  std::string name;
  std::string size;
  std::vector<Piece> pieces;
  std::vector<Stitch> stitches;
  /// What an importer tolerated or repaired ("piece 'back': reversed clockwise outline"), for reports.
  std::vector<std::string> warnings;
};

/// Closed seam-line outline of a piece as one polygon (edge polylines joined, no repeats).
Polygon outline(const Piece& piece);

/// Arc length of an edge polyline in mm.
double edge_length_mm(const Edge& edge);

/// Index of the piece named `name`, or -1.
int find_piece(const Pattern& pattern, const std::string& name);

/// Index of the edge named `name` in `piece`, or -1.
int find_edge(const Piece& piece, const std::string& name);

/// Point at arc length `s_mm` from the edge start (clamped to the edge).
Vec2 point_along_edge(const Edge& edge, double s_mm);

/// Unit tangent at arc length `s_mm` (direction of travel); zero for a degenerate edge.
Vec2 tangent_along_edge(const Edge& edge, double s_mm);

/// Resolved [from, to] of a span in mm from the edge start (to_mm < 0 means the edge end).
std::array<double, 2> span_range_mm(const Pattern& pattern, const EdgeSpan& span);

/// Length of a span in mm (0 when it names no existing edge).
double span_length_mm(const Pattern& pattern, const EdgeSpan& span);

/// "piece 'front' edge 'side' (2)" for messages; tolerant of out-of-range indices.
std::string describe_edge(const Pattern& pattern, int piece, int edge);

}  // namespace tp::geometry
