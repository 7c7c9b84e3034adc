// tests/geometry/pattern/copies_test.cpp: quantities, mirrored pairs and the outline reversal they rely on.
#include "geometry/pattern/copies.h"

#include <gtest/gtest.h>

#include "geometry/pattern/curve.h"
#include "geometry/pattern/mirror.h"
#include "geometry/pattern/orient.h"
#include "geometry/pattern/placement.h"

namespace tp::geometry {
namespace {

Piece sleeve() {
  Piece p;
  p.name = "sleeve";
  p.edges.push_back(make_line_edge("hem", {0, 0}, {300, 0}));
  p.edges.push_back(make_line_edge("front", {300, 0}, {250, 400}));
  p.edges.push_back(make_line_edge("cap", {250, 400}, {50, 400}));
  p.edges.push_back(make_line_edge("back", {50, 400}, {0, 0}));
  p.notches.push_back(Notch{"n", 2, 50});
  p.darts.push_back(Dart{"d", 1, 3});
  p.grain = GrainLine{{150, 50}, {150, 350}};
  Placement3d pl;
  pl.rotation = rotation_from_euler_xyz_deg(0, 30, 0);
  pl.translation_mm = {200, 1200, 50};
  p.placement = pl;
  return p;
}

TEST(Copies, MirroredPairIsLeftAndRight) {
  auto pieces = expand_copies(sleeve(), 2, true);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].name, "sleeve_l");
  EXPECT_EQ(pieces[1].name, "sleeve_r");
  EXPECT_EQ(pieces[1].source_piece, "sleeve");
  EXPECT_FALSE(pieces[0].mirrored);
  EXPECT_TRUE(pieces[1].mirrored);
  // Same area, still counter-clockwise, x mirrored.
  EXPECT_NEAR(signed_area(outline(pieces[1])), signed_area(outline(pieces[0])), 1e-9);
  EXPECT_NEAR(bounds(outline(pieces[1])).min.x, -300, 1e-9);
  // The notch 50 mm along "cap" is at (200, 400); mirrored it is at (-200, 400) on "cap".
  const Piece& m = pieces[1];
  const Notch& n = m.notches[0];
  EXPECT_EQ(m.edges[n.edge].name, "cap");
  Vec2 at = point_along_edge(m.edges[n.edge], n.position_mm);
  EXPECT_NEAR(at.x, -200, 1e-9);
  EXPECT_NEAR(at.y, 400, 1e-9);
  EXPECT_EQ(m.edges[m.darts[0].leg_a].name, "back");
  // Mirrored placement: each piece point lands at the mirror image (x -> -x) of its original.
  Vec3 orig = place_point(*pieces[0].placement, {300, 0});
  Vec3 mirr = place_point(*m.placement, {-300, 0});
  EXPECT_NEAR(mirr.x, -orig.x, 1e-9);
  EXPECT_NEAR(mirr.y, orig.y, 1e-9);
  EXPECT_NEAR(mirr.z, orig.z, 1e-9);
}

TEST(Copies, NamesForQuantities) {
  auto four = expand_copies(sleeve(), 4, true, DraftedSide::kRight);
  ASSERT_EQ(four.size(), 4u);
  EXPECT_EQ(four[0].name, "sleeve_r1");
  EXPECT_EQ(four[1].name, "sleeve_l1");
  EXPECT_EQ(four[3].name, "sleeve_l2");
  auto three = expand_copies(sleeve(), 3, false);
  ASSERT_EQ(three.size(), 3u);
  EXPECT_EQ(three[2].name, "sleeve_3");
  EXPECT_FALSE(three[2].mirrored);
  auto one = expand_copies(sleeve(), 1, true);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].name, "sleeve");
  EXPECT_TRUE(expand_copies(sleeve(), 0, false).empty());
}

TEST(Orient, ReversingClockwisePiecesKeepsStitchesOnTheSamePlace) {
  Pattern pat;
  Piece cw;
  cw.name = "cw";
  cw.edges.push_back(make_line_edge("a", {0, 0}, {0, 100}));
  cw.edges.push_back(make_line_edge("b", {0, 100}, {100, 100}));
  cw.edges.push_back(make_line_edge("c", {100, 100}, {0, 0}));
  pat.pieces.push_back(cw);
  pat.pieces.push_back(sleeve());
  pat.stitches.push_back(Stitch{EdgeSpan{0, 0, 10, 40}, EdgeSpan{1, 3, 0, 30}});
  auto reversed = orient_counter_clockwise(pat);
  ASSERT_EQ(reversed, std::vector<std::string>{"cw"});
  EXPECT_GT(signed_area(outline(pat.pieces[0])), 0);
  const Stitch& s = pat.stitches[0];
  EXPECT_EQ(pat.pieces[0].edges[s.a.edge].name, "a");
  // The span covered y in [10, 40] on "a"; it still does, now measured from the other end.
  auto r = span_range_mm(pat, s.a);
  Vec2 p0 = point_along_edge(pat.pieces[0].edges[s.a.edge], r[0]);
  Vec2 p1 = point_along_edge(pat.pieces[0].edges[s.a.edge], r[1]);
  EXPECT_NEAR(std::min(p0.y, p1.y), 10, 1e-9);
  EXPECT_NEAR(std::max(p0.y, p1.y), 40, 1e-9);
  EXPECT_TRUE(s.same_direction);
}

}  // namespace
}  // namespace tp::geometry
