// tests/geometry/pattern/unfold_test.cpp: cut-on-fold halves opened into whole pieces.
#include "geometry/pattern/unfold.h"

#include <gtest/gtest.h>

#include "geometry/pattern/curve.h"
#include "geometry/pattern/validate.h"

namespace tp::geometry {
namespace {

/// A half bodice: fold along x = 0 from the neck (0, 500) down to the hem (0, 0).
Piece half_front() {
  Piece p;
  p.name = "front";
  p.edges.push_back(make_line_edge("hem", {0, 0}, {200, 0}));
  p.edges.push_back(make_line_edge("side", {200, 0}, {200, 400}));
  p.edges.push_back(make_line_edge("shoulder", {200, 400}, {80, 560}));
  Edge neck{"neck", EdgeCurve::kCubic, {{70, 520}, {30, 500}}, {}};
  EXPECT_TRUE(flatten_edge(neck, {80, 560}, {0, 500}).has_value());
  p.edges.push_back(neck);
  p.edges.push_back(make_line_edge("cf", {0, 500}, {0, 0}));
  p.notches.push_back(Notch{"side_notch", 1, 100});
  p.notches.push_back(Notch{"cf_neck", 4, 0});    // at the neck end of the fold
  p.notches.push_back(Notch{"bust", 4, 250});     // inside the fold: becomes a mark
  p.drill_holes.push_back(DrillHole{{100, 300}, 3});
  p.internal_lines.push_back(InternalLine{"pocket", {{50, 100}, {150, 100}}});
  p.internal_lines.push_back(InternalLine{"cf_line", {{0, 100}, {0, 200}}});
  return p;
}

TEST(Unfold, MirrorsTheHalfAcrossTheFold) {
  auto r = unfold_piece(half_front(), 4);
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Piece& w = *r;
  Pattern pat;
  pat.pieces.push_back(w);
  Status s = validate_pattern(pat);
  EXPECT_TRUE(s.has_value()) << s.error().what();
  // Twice the half's area: half = 200x400 + trapezoid-ish top; compare with the half directly.
  Piece half = half_front();
  Polygon hp = outline(half);
  EXPECT_NEAR(signed_area(outline(w)), 2 * signed_area(hp), 1e-6);
  // hem and neck cross the fold: single edges; side and shoulder come twice.
  std::vector<std::string> names;
  for (const Edge& e : w.edges) names.push_back(e.name);
  EXPECT_EQ(names, (std::vector<std::string>{"hem", "side", "shoulder", "neck", "shoulder_mirror", "side_mirror"}));
  EXPECT_NEAR(edge_length_mm(w.edges[0]), 400, 1e-9);
  EXPECT_EQ(w.edges[0].curve, EdgeCurve::kLine);
  EXPECT_EQ(w.edges[3].curve, EdgeCurve::kCubic);
  ASSERT_TRUE(w.fold_line_mm.has_value());
  EXPECT_FALSE(w.fold_edge.has_value());
}

TEST(Unfold, CarriesNotchesMarksAndLines) {
  auto r = unfold_piece(half_front(), 4);
  ASSERT_TRUE(r.has_value());
  const Piece& w = *r;
  // side notch twice, the neck-end notch once at the centre of the neck edge.
  ASSERT_EQ(w.notches.size(), 3u);
  int side_mirror = find_edge(w, "side_mirror");
  bool mirrored_side_notch = false, neck_centre = false;
  for (const Notch& n : w.notches) {
    Vec2 at = point_along_edge(w.edges[n.edge], n.position_mm);
    if (n.edge == side_mirror) {
      mirrored_side_notch = true;
      EXPECT_NEAR(at.x, -200, 1e-9);
      EXPECT_NEAR(at.y, 100, 1e-9);
    }
    if (n.name == "cf_neck") {
      neck_centre = true;
      EXPECT_NEAR(at.x, 0, 1e-9);
      EXPECT_NEAR(at.y, 500, 1e-9);
    }
  }
  EXPECT_TRUE(mirrored_side_notch);
  EXPECT_TRUE(neck_centre);
  // The drill hole is mirrored; the fold notch at 250 mm is a mark (diameter 0) on the fold.
  ASSERT_EQ(w.drill_holes.size(), 3u);
  EXPECT_EQ(w.drill_holes[2].position_mm, (Vec2{-100, 300}));
  EXPECT_EQ(w.drill_holes[0].diameter_mm, 0);
  // The pocket line is mirrored; the line on the fold is kept once.
  EXPECT_EQ(w.internal_lines.size(), 3u);
}

TEST(Unfold, RejectsACurvedOrMissingFold) {
  EXPECT_FALSE(unfold_piece(half_front(), 9).has_value());
  auto r = unfold_piece(half_front(), 3);
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("piece 'front': fold edge 'neck' is not straight"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace tp::geometry
