// tests/geometry/pattern/pattern_test.cpp: outline assembly and edge queries of the pattern model.
#include "geometry/pattern/pattern.h"

#include <gtest/gtest.h>

namespace tp::geometry {
namespace {

Piece square_piece() {
  Piece p;
  p.name = "square";
  const Vec2 c[4] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  const char* names[4] = {"bottom", "right", "top", "left"};
  for (int i = 0; i < 4; ++i) p.edges.push_back(Edge{names[i], EdgeCurve::kLine, {}, {c[i], c[(i + 1) % 4]}});
  return p;
}

TEST(Pattern, OutlineJoinsEdgesWithoutRepeats) {
  Polygon poly = outline(square_piece());
  ASSERT_EQ(poly.size(), 4u);
  EXPECT_DOUBLE_EQ(signed_area(poly), 10000.0);
}

TEST(Pattern, FindsPiecesAndEdgesByName) {
  Pattern pat;
  pat.pieces.push_back(square_piece());
  EXPECT_EQ(find_piece(pat, "square"), 0);
  EXPECT_EQ(find_piece(pat, "circle"), -1);
  EXPECT_EQ(find_edge(pat.pieces[0], "top"), 2);
  EXPECT_DOUBLE_EQ(edge_length_mm(pat.pieces[0].edges[1]), 100.0);
}

}  // namespace
}  // namespace tp::geometry
