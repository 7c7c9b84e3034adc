// tests/geometry/mesh/mesh_pattern_test.cpp: seam-matched meshing of pattern pieces.
#include "geometry/mesh/mesh_pattern.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/mesh/sample_boundary.h"

namespace tp::geometry {
namespace {

Edge line_edge(const std::string& name, Vec2 a, Vec2 b) {
  return Edge{name, EdgeCurve::kLine, {}, {a, b}};
}

// A quarter-circle-ish polyline edge from a to b bulging outwards by `bulge_mm`.
Edge curved_edge(const std::string& name, Vec2 a, Vec2 b, double bulge_mm) {
  Edge e{name, EdgeCurve::kPolyline, {}, {}};
  Vec2 n = perp(normalized(b - a)) * -1.0;
  for (int i = 0; i <= 40; ++i) {
    double t = i / 40.0;
    e.points_mm.push_back(a + (b - a) * t + n * (bulge_mm * 4 * t * (1 - t)));
  }
  return e;
}

// Piece 0: 300 x 200 rectangle whose right edge bulges; piece 1: rectangle whose left edge is
// straight with the bulged edge's length, so the two can be sewn.
Pattern two_pieces() {
  Pattern p;
  p.name = "test";
  Piece a;
  a.name = "left";
  a.edges = {line_edge("bottom", {0, 0}, {300, 0}), curved_edge("side", {300, 0}, {300, 200}, 30),
             line_edge("top", {300, 200}, {0, 200}), line_edge("cf", {0, 200}, {0, 0})};
  double l = edge_length_mm(a.edges[1]);
  Piece b;
  b.name = "right";
  b.edges = {line_edge("bottom", {0, 0}, {150, 0}), line_edge("side", {150, 0}, {150, l}),
             line_edge("top", {150, l}, {0, l}), line_edge("seam", {0, l}, {0, 0})};
  p.pieces = {a, b};
  p.stitches.push_back(Stitch{EdgeSpan{0, 1, 0, -1}, EdgeSpan{1, 3, 0, -1}, false});
  return p;
}

double mesh_area(const PieceMesh& m) {
  double s = 0;
  for (auto t : m.triangles) {
    double a = 0.5 * cross(m.vertices_mm[t[1]] - m.vertices_mm[t[0]], m.vertices_mm[t[2]] - m.vertices_mm[t[0]]);
    EXPECT_GT(a, 0) << "clockwise or degenerate triangle";
    s += a;
  }
  return s;
}

TEST(MeshPattern, StitchedSpansGetMatchingVerticesAtMatchingArcLengths) {
  Pattern p = two_pieces();
  auto pm = mesh_pattern(p, TriangulateOptions{.target_edge_mm = 15});
  ASSERT_TRUE(pm) << pm.error().what();
  ASSERT_EQ(pm->stitch_vertices.size(), 1u);
  const auto& pairs = pm->stitch_vertices[0];
  const auto& ea = pm->pieces[0].edge_vertices[1];
  const auto& eb = pm->pieces[1].edge_vertices[3];
  ASSERT_EQ(ea.size(), eb.size());
  ASSERT_EQ(pairs.size(), ea.size());
  // a's start meets b's end: the pairs run along a forwards and along b backwards.
  EXPECT_EQ(pairs.front()[0], ea.front());
  EXPECT_EQ(pairs.front()[1], eb.back());
  // Matching arc-length positions: cumulative lengths along each side agree.
  double sa = 0, sb = 0;
  for (size_t k = 1; k < pairs.size(); ++k) {
    sa += norm(pm->pieces[0].vertices_mm[pairs[k][0]] - pm->pieces[0].vertices_mm[pairs[k - 1][0]]);
    sb += norm(pm->pieces[1].vertices_mm[pairs[k][1]] - pm->pieces[1].vertices_mm[pairs[k - 1][1]]);
    EXPECT_NEAR(sa, sb, 0.02 * sa + 0.1) << "pair " << k;
  }
}

TEST(MeshPattern, MeshCoversThePieceAndKeepsTheBoundary) {
  Pattern p = two_pieces();
  auto pm = mesh_pattern(p, TriangulateOptions{.target_edge_mm = 12});
  ASSERT_TRUE(pm) << pm.error().what();
  for (size_t i = 0; i < p.pieces.size(); ++i) {
    const PieceMesh& m = pm->pieces[i];
    auto sampled = sample_boundary(p, 12);
    ASSERT_TRUE(sampled);
    double ring_area = signed_area(sampled->pieces[i].ring_mm);
    EXPECT_NEAR(mesh_area(m), ring_area, 1e-6 * ring_area);
    EXPECT_NEAR(std::abs(ring_area), std::abs(signed_area(outline(p.pieces[i]))), 0.01 * std::abs(ring_area));
    // Edges follow the size bound: refinement meets it, Lloyd smoothing may stretch a few.
    double sum = 0;
    int count = 0;
    for (auto t : m.triangles)
      for (int k = 0; k < 3; ++k) {
        double l = norm(m.vertices_mm[t[k]] - m.vertices_mm[t[(k + 1) % 3]]);
        EXPECT_LT(l, 12 * 1.4);
        sum += l, ++count;
      }
    EXPECT_LT(sum / count, 12.0);
    // Edge vertex lists chain around the outline.
    for (size_t e = 0; e < m.edge_vertices.size(); ++e)
      EXPECT_EQ(m.edge_vertices[e].back(), m.edge_vertices[(e + 1) % m.edge_vertices.size()].front());
  }
}

TEST(MeshPattern, VertexCountFollowsTarget) {
  Pattern p = two_pieces();
  double h = target_edge_for_vertex_count(p, 2000);
  auto pm = mesh_pattern(p, TriangulateOptions{.target_edge_mm = h});
  ASSERT_TRUE(pm);
  size_t n = pm->pieces[0].vertices_mm.size() + pm->pieces[1].vertices_mm.size();
  EXPECT_GT(n, 1400u);
  EXPECT_LT(n, 2800u);
}

TEST(MeshPattern, PartialSpansSplitAnEdge) {
  Pattern p = two_pieces();
  double l = edge_length_mm(p.pieces[0].edges[1]);
  // Sew only the upper half of the bulged edge, to the lower half of piece 1's seam.
  p.stitches[0] = Stitch{EdgeSpan{0, 1, l / 2, -1}, EdgeSpan{1, 3, l / 2, -1}, false};
  auto pm = mesh_pattern(p, TriangulateOptions{.target_edge_mm = 20});
  ASSERT_TRUE(pm) << pm.error().what();
  const auto& pairs = pm->stitch_vertices[0];
  Vec2 first_a = pm->pieces[0].vertices_mm[pairs.front()[0]];
  Vec2 expect_a = point_at_arc_length(p.pieces[0].edges[1].points_mm, l / 2);
  EXPECT_NEAR(norm(first_a - expect_a), 0, 1e-6);
  // a's start meets b's end, which is the end of piece 1's seam edge.
  EXPECT_EQ(pairs.front()[1], pm->pieces[1].edge_vertices[3].back());
}

TEST(MeshPattern, ErrorsNameThePieceAndEdge) {
  Pattern p = two_pieces();
  p.stitches[0].b.edge = 9;
  auto r = mesh_pattern(p, TriangulateOptions{});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("'right'"), std::string::npos) << r.error().message;
  EXPECT_EQ(r.error().code, ErrorCode::kUnknownReference);

  p = two_pieces();
  p.pieces[1].edges[2].points_mm[1] = p.pieces[1].edges[2].points_mm[0];
  p.pieces[1].edges[2].points_mm[1] = p.pieces[1].edges[2].points_mm[0];
  p.pieces[1].edges[3].points_mm[0] = p.pieces[1].edges[2].points_mm[0];
  r = mesh_pattern(p, TriangulateOptions{});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("edge 'top' has zero length"), std::string::npos) << r.error().message;

  p = two_pieces();
  p.stitches.push_back(Stitch{EdgeSpan{0, 1, 10, 60}, EdgeSpan{1, 1, 0, 50}, false});
  r = mesh_pattern(p, TriangulateOptions{});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("overlap"), std::string::npos) << r.error().message;
}

TEST(TriangulatePolygon, RejectsSelfIntersectingOutline) {
  std::vector<Vec2> bow{{0, 0}, {100, 100}, {100, 0}, {0, 100}};
  auto r = triangulate_polygon(bow, TriangulateOptions{});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("cross"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
