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

TEST(Pattern, PointsAndTangentsAlongAnEdge) {
  Edge e{"l", EdgeCurve::kPolyline, {}, {{0, 0}, {10, 0}, {10, 0}, {10, 20}}};
  EXPECT_EQ(point_along_edge(e, -5), (Vec2{0, 0}));
  EXPECT_EQ(point_along_edge(e, 5), (Vec2{5, 0}));
  EXPECT_EQ(point_along_edge(e, 20), (Vec2{10, 10}));
  EXPECT_EQ(point_along_edge(e, 99), (Vec2{10, 20}));
  // The zero-length segment at the corner is skipped.
  EXPECT_EQ(tangent_along_edge(e, 5), (Vec2{1, 0}));
  EXPECT_EQ(tangent_along_edge(e, 15), (Vec2{0, 1}));
}

TEST(Pattern, SpansResolveTheirEnd) {
  Pattern pat;
  pat.pieces.push_back(square_piece());
  EXPECT_EQ(span_range_mm(pat, EdgeSpan{0, 1, 10, -1}), (std::array<double, 2>{10, 100}));
  EXPECT_DOUBLE_EQ(span_length_mm(pat, EdgeSpan{0, 1, 10, 40}), 30.0);
  EXPECT_DOUBLE_EQ(span_length_mm(pat, EdgeSpan{3, 1, 0, -1}), 0.0);
  EXPECT_EQ(describe_edge(pat, 0, 2), "piece 'square' edge 'top' (2)");
  EXPECT_EQ(describe_edge(pat, 0, 7), "piece 'square' edge #7");
  EXPECT_EQ(describe_edge(pat, 4, 0), "piece #4");
}

}  // namespace
}  // namespace tp::geometry
