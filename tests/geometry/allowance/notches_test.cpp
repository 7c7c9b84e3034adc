// tests/geometry/allowance/notches_test.cpp: notch positions (pattern, stitch ends, balance) and shapes.
#include "geometry/allowance/notches.h"

#include <gtest/gtest.h>

#include "geometry/allowance/cut_outline.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

TEST(PieceNotches, StitchEndsBalanceAndPatternNotchesAreCutIntoTheAllowance) {
  auto g = test::gore_skirt(4);
  // Sew only the lower half of gore0's right edge to gore1: its end (mid-edge) is a stitch end.
  const double len = edge_length_mm(g.pattern.pieces[0].edges[1]);
  g.pattern.stitches[0].a.to_mm = 0.5 * len;
  g.pattern.stitches[0].b.from_mm = 0.5 * edge_length_mm(g.pattern.pieces[1].edges[3]);
  g.pattern.pieces[0].notches.push_back({"hip", 3, 100, NotchType::kV});
  Finishing f;
  auto a = resolve_allowance(g.pattern, 0, f);
  ASSERT_TRUE(a);
  auto cut = cut_outline(g.pattern.pieces[0], *a, f.mitre_limit);
  ASSERT_TRUE(cut);
  const auto notches = piece_notches(g.pattern, 0, *a, *cut, f);
  int stitch_end = 0, balance = 0, hip = 0;
  for (const NotchCut& n : notches) {
    // Every notch opens on the cut line, allowance width outside the seam line, and stays out
    // of the piece: its depth is at most 60 % of the allowance.
    EXPECT_NEAR(norm(n.cut_point_mm - n.seam_point_mm), a->width_mm[static_cast<size_t>(n.edge)], 1e-6) << n.name;
    EXPECT_LE(n.depth_mm, 0.6 * a->width_mm[static_cast<size_t>(n.edge)] + 1e-9);
    if (n.name == "stitch_end") {
      ++stitch_end;
      EXPECT_EQ(n.edge, 1);
      EXPECT_NEAR(n.position_mm, 0.5 * len, 1e-9);
    }
    if (n.name == "balance") {
      ++balance;
      EXPECT_EQ(n.edge, 1);
      EXPECT_NEAR(n.position_mm, 0.25 * len, 1e-9);
    }
    if (n.name == "hip") {
      ++hip;
      ASSERT_EQ(n.strokes.size(), 1u);
      EXPECT_EQ(n.strokes[0].size(), 3u);  // V: mouth, tip, mouth
      EXPECT_NEAR(norm(n.strokes[0][0] - n.strokes[0][2]), f.notch_width_mm, 1e-9);
    }
  }
  EXPECT_EQ(stitch_end, 1);
  EXPECT_EQ(hip, 1);
  // The 300 mm half-seam is long enough for a balance notch; the left seam is long too, but its
  // own "hip" notch already matches it.
  EXPECT_EQ(balance, 1);
}

}  // namespace
}  // namespace tp::geometry
