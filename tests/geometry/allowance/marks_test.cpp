// tests/geometry/allowance/marks_test.cpp: the stroke font and label/grain placement in the allowance.
#include "geometry/allowance/marks.h"

#include <gtest/gtest.h>

#include "geometry/allowance/cut_outline.h"
#include "geometry/allowance/stroke_font.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

TEST(StrokeFont, HasCapitalsDigitsAndSymbolsScaledToTheCapHeight) {
  for (char c = 'A'; c <= 'Z'; ++c) EXPECT_TRUE(font_has_glyph(c)) << c;
  for (char c = '0'; c <= '9'; ++c) EXPECT_TRUE(font_has_glyph(c)) << c;
  for (char c : std::string("-./:#()+")) EXPECT_TRUE(font_has_glyph(c)) << c;
  EXPECT_TRUE(font_has_glyph('q'));  // drawn as a capital
  EXPECT_FALSE(font_has_glyph('~'));
  const auto strokes = text_strokes("H1", 6);
  Box2 b;
  for (const auto& s : strokes)
    for (Vec2 p : s) b.add(p);
  EXPECT_NEAR(b.min.y, 0, 1e-9);
  EXPECT_NEAR(b.max.y, 6, 1e-9);
  EXPECT_NEAR(text_width_mm("H1", 6), 10, 1e-9);
  EXPECT_LE(b.max.x, text_width_mm("H1", 6) + 1e-9);
}

TEST(PieceMarks, LabelAndGrainArrowLieInTheAllowance) {
  auto g = test::gore_skirt(8);
  Finishing f;
  f.job_name = "J42";
  const Piece& pc = g.pattern.pieces[0];
  auto a = resolve_allowance(g.pattern, 0, f);
  ASSERT_TRUE(a);
  const PieceMarks m = piece_marks(pc, *a, g.pattern.size, f);
  EXPECT_EQ(m.text, "GORE0 M J42");
  EXPECT_TRUE(m.in_allowance);
  ASSERT_FALSE(m.label.empty());
  ASSERT_FALSE(m.grain_arrow.empty());
  auto cut = cut_outline(pc, *a, f.mitre_limit);
  ASSERT_TRUE(cut);
  const Polygon seam = outline(pc);
  // Every stroke point is outside the seam line and inside the cut line: hidden once sewn.
  for (const auto* set : {&m.label, &m.grain_arrow})
    for (const auto& line : *set)
      for (Vec2 p : line) {
        EXPECT_FALSE(point_in_polygon(seam, p)) << p.x << "," << p.y;
        EXPECT_TRUE(point_in_polygon(*cut, p)) << p.x << "," << p.y;
      }
  // The arrow's shaft runs along the grain line.
  const Vec2 shaft = m.grain_arrow[0][1] - m.grain_arrow[0][0];
  const Vec2 grain = pc.grain->to_mm - pc.grain->from_mm;
  EXPECT_NEAR(std::abs(cross(normalized(shaft), normalized(grain))), 0, 1e-9);
}

TEST(PieceMarks, WithoutAllowanceTheLabelGoesJustInsideTheSeamLine) {
  auto g = test::gore_skirt(8);
  Finishing f;
  f.seam_allowance_mm = f.hem_allowance_mm = f.edge_allowance_mm = 0;
  auto a = resolve_allowance(g.pattern, 0, f);
  ASSERT_TRUE(a);
  const PieceMarks m = piece_marks(g.pattern.pieces[0], *a, "M", f);
  EXPECT_FALSE(m.in_allowance);
  EXPECT_FALSE(m.label.empty());
  EXPECT_TRUE(m.grain_arrow.empty());
}

}  // namespace
}  // namespace tp::geometry
