// geometry/samples/internal/draft.h: drafting helpers shared by the sample garments (edges, darts, mirroring).
#pragma once

#include <string>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::samples::internal {

/// Builds a closed outline edge by edge from a start point (counter-clockwise seen from the
/// right side of the fabric).
class OutlineBuilder {
 public:
  explicit OutlineBuilder(Vec2 start_mm) : cursor_(start_mm), start_(start_mm) {}
  OutlineBuilder& line(const std::string& name, Vec2 to_mm);
  OutlineBuilder& quad(const std::string& name, Vec2 control_mm, Vec2 to_mm);
  OutlineBuilder& cubic(const std::string& name, Vec2 c1_mm, Vec2 c2_mm, Vec2 to_mm);
  /// A polyline edge through `points_mm` (the cursor is its start; the last point its end).
  OutlineBuilder& polyline(const std::string& name, const std::vector<Vec2>& points_mm);
  /// Closes the outline: the last edge must end at the start point.
  std::vector<Edge> edges() const { return edges_; }
  Vec2 cursor() const { return cursor_; }

 private:
  std::vector<Edge> edges_;
  Vec2 cursor_, start_;
};

/// Points of a cubic Bezier, `segments` + 1 of them.
std::vector<Vec2> cubic_points(Vec2 p0, Vec2 c1, Vec2 c2, Vec2 p1, int segments);

/// Cuts a dart into edge `edge` of `piece`: its mouth is centred at arc length `centre_mm`
/// along the edge, `width_mm` wide (along the edge), and its point at `apex_mm`, moved onto
/// the mouth's perpendicular bisector so both legs have the same length. The edge becomes
/// <edge>, <dart>_a (mouth to point), <dart>_b (point to mouth), <edge>_2; a Dart records the
/// legs. Returns the indices of the two legs.
std::pair<int, int> cut_dart(Piece& piece, int edge, double centre_mm, double width_mm, Vec2 apex_mm,
                             const std::string& dart_name);

/// The mirror image (x -> -x) of a piece, outline kept counter-clockwise: edges reversed,
/// notches and darts remapped, grain mirrored, `mirrored` set; a placement is mirrored across
/// the body's x = 0 plane.
Piece mirror_piece(const Piece& piece, const std::string& name);

/// Placement rotating the piece by `theta_rad` about the vertical axis (piece +z faces the
/// direction (sin theta, 0, cos theta)), then translating by `t_mm`.
Placement3d placement_about_y(double theta_rad, Vec3 t_mm);

/// Adds a stitch between whole or partial edges named by piece and edge names. Spans are
/// [from, to] mm (to < 0: the edge's end). Fails with kUnknownReference naming the missing name.
[[nodiscard]] Status add_stitch(Pattern& p, const std::string& piece_a, const std::string& edge_a,
                                const std::string& piece_b, const std::string& edge_b, double a_from = 0,
                                double a_to = -1, double b_from = 0, double b_to = -1);

/// Adds the stitch sewing the two legs of every dart of every piece.
[[nodiscard]] Status stitch_darts(Pattern& p);

/// Total arc length of the named edge of the named piece (0 if missing).
double edge_length(const Pattern& p, const std::string& piece, const std::string& edge);

/// Adds a notch at arc length `position_mm` along the named edge.
void add_notch(Piece& piece, const std::string& edge, double position_mm, const std::string& name);

}  // namespace tp::geometry::samples::internal
