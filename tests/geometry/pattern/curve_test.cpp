// tests/geometry/pattern/curve_test.cpp: flattening within the chord tolerance, exact reversal and joining.
#include "geometry/pattern/curve.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tp::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec2 cubic_at(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double t) {
  double u = 1 - t;
  return a * (u * u * u) + b * (3 * u * u * t) + c * (3 * u * t * t) + d * (t * t * t);
}

double distance_to_polyline(Vec2 p, const std::vector<Vec2>& pl) {
  double best = 1e300;
  for (size_t i = 1; i < pl.size(); ++i) {
    Vec2 ab = pl[i] - pl[i - 1];
    double t = std::clamp(dot(p - pl[i - 1], ab) / std::max(dot(ab, ab), 1e-300), 0.0, 1.0);
    best = std::min(best, norm(p - (pl[i - 1] + ab * t)));
  }
  return best;
}

TEST(Curve, CubicFlattensWithinTheChordTolerance) {
  Vec2 a{0, 0}, b{30, 120}, c{170, -80}, d{200, 40};
  for (double tol : {0.5, 0.05, 0.005}) {
    Edge e{"s", EdgeCurve::kCubic, {b, c}, {}};
    ASSERT_TRUE(flatten_edge(e, a, d, tol).has_value());
    EXPECT_EQ(e.points_mm.front(), a);
    EXPECT_EQ(e.points_mm.back(), d);
    double worst = 0;
    for (int i = 0; i <= 2000; ++i) worst = std::max(worst, distance_to_polyline(cubic_at(a, b, c, d, i / 2000.0), e.points_mm));
    EXPECT_LE(worst, tol) << "tolerance " << tol;
    // Not wastefully fine either: the polyline is within an order of magnitude of the tolerance.
    EXPECT_GT(worst, tol / 20) << "tolerance " << tol;
  }
}

TEST(Curve, QuadraticChainPassesThroughItsJoints) {
  Edge e{"q", EdgeCurve::kQuadratic, {{50, 50}, {100, 0}, {150, -50}}, {}};
  ASSERT_TRUE(flatten_edge(e, {0, 0}, {200, 0}, 0.01).has_value());
  bool joint = false;
  for (Vec2 p : e.points_mm) joint = joint || (p == Vec2{100, 0});
  EXPECT_TRUE(joint);
  // Each quadratic peaks at half its control height: 25 mm.
  double top = 0;
  for (Vec2 p : e.points_mm) top = std::max(top, p.y);
  EXPECT_NEAR(top, 25, 0.01);
}

TEST(Curve, ArcFollowsItsCircleTheWayOfItsMidPoint) {
  // Upper half circle of radius 100 from (100, 0) to (-100, 0) through (0, 100).
  Edge e{"a", EdgeCurve::kArc, {{}, {0, 100}}, {}};
  ASSERT_TRUE(flatten_edge(e, {100, 0}, {-100, 0}, 0.01).has_value());
  EXPECT_NEAR(e.control_mm[0].x, 0, 1e-9);
  EXPECT_NEAR(e.control_mm[0].y, 0, 1e-9);
  for (Vec2 p : e.points_mm) {
    EXPECT_NEAR(norm(p), 100, 1e-9);
    EXPECT_GE(p.y, -1e-9);
  }
  EXPECT_NEAR(edge_length_mm(e), 100 * kPi, 0.05);
  // The same ends through (0, -100) go round the lower half.
  Edge f{"b", EdgeCurve::kArc, {{}, {0, -100}}, {}};
  ASSERT_TRUE(flatten_edge(f, {100, 0}, {-100, 0}, 0.01).has_value());
  for (Vec2 p : f.points_mm) EXPECT_LE(p.y, 1e-9);
}

TEST(Curve, MalformedCurvesFailWithTheEdgeName) {
  Edge e{"bad", EdgeCurve::kCubic, {{1, 1}}, {}};
  auto s = flatten_edge(e, {0, 0}, {1, 0});
  ASSERT_FALSE(s.has_value());
  EXPECT_NE(s.error().message.find("edge 'bad'"), std::string::npos);
  Edge line_arc{"flat", EdgeCurve::kArc, {{}, {5, 0}}, {}};
  s = flatten_edge(line_arc, {0, 0}, {10, 0});
  ASSERT_FALSE(s.has_value());
  EXPECT_NE(s.error().message.find("collinear"), std::string::npos);
  Edge inf{"inf", EdgeCurve::kLine, {}, {}};
  EXPECT_FALSE(flatten_edge(inf, {0, 0}, {INFINITY, 0}).has_value());
  // A huge arc at the smallest tolerance would need too many points.
  Edge huge{"huge", EdgeCurve::kArc, {{}, {0, 1e9}}, {}};
  EXPECT_FALSE(flatten_edge(huge, {1e9, 0}, {-1e9, 0}, 0).has_value());
}

TEST(Curve, ReversedEdgeRetracesTheSameCurve) {
  Edge e{"s", EdgeCurve::kCubic, {{30, 120}, {170, -80}, {200, 40}, {220, 60}, {260, 0}}, {}};
  ASSERT_TRUE(flatten_edge(e, {0, 0}, {300, 10}, 0.01).has_value());
  Edge r = reversed_edge(e);
  EXPECT_EQ(r.points_mm.front(), e.points_mm.back());
  Edge again = r;
  ASSERT_TRUE(flatten_edge(again, r.points_mm.front(), r.points_mm.back(), 0.01).has_value());
  EXPECT_NEAR(edge_length_mm(again), edge_length_mm(e), 1e-3);
  for (Vec2 p : again.points_mm) EXPECT_LE(distance_to_polyline(p, e.points_mm), 0.02);
}

TEST(Curve, JoiningKeepsExactCurvesWherePossible) {
  Edge a = make_line_edge("a", {0, 0}, {10, 0});
  Edge b = make_line_edge("b", {10, 0}, {30, 0});
  Edge j = joined_edges(a, b);
  EXPECT_EQ(j.curve, EdgeCurve::kLine);
  EXPECT_EQ(j.points_mm.size(), 2u);
  EXPECT_EQ(j.name, "a");
  // Two quarter arcs of the unit circle join into one half arc.
  Edge q1{"q1", EdgeCurve::kArc, {{}, {std::sqrt(0.5) * 100, std::sqrt(0.5) * 100}}, {}};
  Edge q2{"q2", EdgeCurve::kArc, {{}, {-std::sqrt(0.5) * 100, std::sqrt(0.5) * 100}}, {}};
  ASSERT_TRUE(flatten_edge(q1, {100, 0}, {0, 100}).has_value());
  ASSERT_TRUE(flatten_edge(q2, {0, 100}, {-100, 0}).has_value());
  Edge half = joined_edges(q1, q2);
  EXPECT_EQ(half.curve, EdgeCurve::kArc);
  ASSERT_TRUE(flatten_edge(half, {100, 0}, {-100, 0}, 0.01).has_value());
  EXPECT_NEAR(edge_length_mm(half), 100 * kPi, 0.05);
  // A line and a cubic join into a cubic chain that reflattens to the same length.
  Edge c{"c", EdgeCurve::kCubic, {{20, 10}, {30, 10}}, {}};
  ASSERT_TRUE(flatten_edge(c, {10, 0}, {40, 0}).has_value());
  Edge lc = joined_edges(a, c);
  EXPECT_EQ(lc.curve, EdgeCurve::kCubic);
  EXPECT_EQ(lc.control_mm.size(), 5u);
  double len = edge_length_mm(lc);
  ASSERT_TRUE(flatten_edge(lc, {0, 0}, {40, 0}).has_value());
  EXPECT_NEAR(edge_length_mm(lc), len, 0.01);
}

}  // namespace
}  // namespace tp::geometry
