// tests/geometry/allowance/cut_outline_test.cpp: cut outlines: uniform and per-edge widths,
// concave corners, curves, narrow parts, reflected and square corners, bad input.
#include "geometry/allowance/cut_outline.h"
#include "geometry/common/segment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tp::geometry {
namespace {

using Edges = std::vector<std::vector<Vec2>>;

Edges polygon_edges(const Polygon& p) {
  Edges e;
  for (size_t i = 0; i < p.size(); ++i) e.push_back({p[i], p[(i + 1) % p.size()]});
  return e;
}

bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 1e-9 && d2 < -1e-9) || (d1 < -1e-9 && d2 > 1e-9)) && ((d3 > 1e-9 && d4 < -1e-9) || (d3 < -1e-9 && d4 > 1e-9));
}

bool is_simple(const Polygon& p) {
  const size_t n = p.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false;
    }
  return true;
}

TEST(CutOutline, UniformMitreOnASquareIsTheLargerSquare) {
  const Polygon sq{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  auto r = cut_outline(polygon_edges(sq), {10, 10, 10, 10}, std::vector<CornerStyle>(4, CornerStyle::kMitre), 3);
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_EQ(r->size(), 4u);
  EXPECT_NEAR(signed_area(*r), 120.0 * 120.0, 1e-6);
  const Box2 b = bounds(*r);
  EXPECT_NEAR(b.min.x, -10, 1e-9);
  EXPECT_NEAR(b.max.y, 110, 1e-9);
}

TEST(CutOutline, PerEdgeWidthsMoveEachSideByItsOwnWidth) {
  const Polygon sq{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  auto r = cut_outline(polygon_edges(sq), {25, 10, 5, 10}, std::vector<CornerStyle>(4, CornerStyle::kMitre), 3);
  ASSERT_TRUE(r) << r.error().what();
  const Box2 b = bounds(*r);
  EXPECT_NEAR(b.min.y, -25, 1e-9);
  EXPECT_NEAR(b.max.x, 110, 1e-9);
  EXPECT_NEAR(b.max.y, 105, 1e-9);
  EXPECT_NEAR(signed_area(*r), 120.0 * 130.0, 1e-6);
}

TEST(CutOutline, ConcaveCornersFollowTheRectilinearOffsetFormula) {
  // An L: area A, perimeter P; a mitred rectilinear offset adds P*w + (convex - concave)*w^2.
  const Polygon l{{0, 0}, {100, 0}, {100, 40}, {40, 40}, {40, 120}, {0, 120}};
  const double w = 10, A = 100 * 40 + 40 * 80, P = 2 * (100 + 120);
  auto r = cut_outline(polygon_edges(l), std::vector<double>(6, w), std::vector<CornerStyle>(6, CornerStyle::kMitre), 3);
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_TRUE(is_simple(*r));
  EXPECT_NEAR(signed_area(*r), A + P * w + 4 * w * w, 1e-6);
}

TEST(CutOutline, CurvedEdgesOffsetToAParallelCurve) {
  Polygon circle;
  for (int i = 0; i < 128; ++i) {
    const double a = 2 * std::numbers::pi * i / 128;
    circle.push_back({50 * std::cos(a), 50 * std::sin(a)});
  }
  std::vector<Vec2> closed = circle;
  closed.push_back(circle.front());
  auto r = cut_outline(Edges{closed}, {10}, {CornerStyle::kMitre}, 3);
  ASSERT_TRUE(r) << r.error().what();
  for (Vec2 p : *r) EXPECT_NEAR(norm(p), 60, 0.05);
  EXPECT_NEAR(signed_area(*r), std::numbers::pi * 3600, 0.005 * std::numbers::pi * 3600);
}

TEST(CutOutline, AllowanceWiderThanANarrowStrapStaysOnePolygon) {
  const Polygon strap{{0, 0}, {5, 0}, {5, 200}, {0, 200}};
  auto r = cut_outline(polygon_edges(strap), {10, 10, 10, 10}, std::vector<CornerStyle>(4, CornerStyle::kMitre), 3);
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_TRUE(is_simple(*r));
  EXPECT_NEAR(signed_area(*r), 25.0 * 220.0, 1e-6);
}

TEST(CutOutline, OverlappingAllowancesInsideANarrowNotchMerge) {
  // A U whose gap (8 mm) is narrower than two allowances (2 x 10 mm): the gap fills in.
  const Polygon u{{0, 0}, {60, 0}, {60, 100}, {34, 100}, {34, 30}, {26, 30}, {26, 100}, {0, 100}};
  auto r = cut_outline(polygon_edges(u), std::vector<double>(8, 10), std::vector<CornerStyle>(8, CornerStyle::kMitre), 3);
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_TRUE(is_simple(*r));
  const Box2 b = bounds(*r);
  EXPECT_NEAR(b.min.x, -10, 1e-9);
  EXPECT_NEAR(b.max.y, 110, 1e-9);
  // Every cut point is at least the allowance away from the seam line.
  for (Vec2 p : *r) {
    double d = 1e9;
    for (size_t i = 0; i < u.size(); ++i) d = std::min(d, distance_to_segment(p, u[i], u[(i + 1) % u.size()]));
    EXPECT_GE(d, 10 - 1e-6);
  }
}

TEST(CutOutline, ReflectedHemCornerFoldsOntoTheSideCutLine) {
  // A flared gore: the hem (edge 0) meets the sides at an angle. Folded up along the hem line,
  // the end of the hem allowance must lie on the side seam's cut line.
  const Polygon gore{{-100, 0}, {100, 0}, {60, 500}, {-60, 500}};
  const double hem = 30, side = 10;
  auto r = cut_outline(polygon_edges(gore), {hem, side, side, side},
                       {CornerStyle::kReflectIncoming, CornerStyle::kMitre, CornerStyle::kMitre, CornerStyle::kReflectOutgoing}, 3);
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_TRUE(is_simple(*r));
  // The lowest points of the outline are the hem's cut line (y = -30); its ends, folded (y -> -y),
  // lie on the side cut lines.
  const Vec2 a = gore[1], b = gore[2];
  const Vec2 out = normalized(Vec2{(b - a).y, -(b - a).x});
  int checked = 0;
  for (Vec2 p : *r) {
    if (std::abs(p.y + hem) > 1e-6 || p.x < 0) continue;
    const Vec2 folded{p.x, -p.y};
    EXPECT_NEAR(dot(folded - a, out), side, 1e-6);
    ++checked;
  }
  EXPECT_EQ(checked, 1);
}

TEST(CutOutline, SquareCornersRunEachAllowanceStraightPastTheCorner) {
  const Polygon tri{{0, 0}, {100, 0}, {0, 60}};
  auto r = cut_outline(polygon_edges(tri), {10, 10, 10}, std::vector<CornerStyle>(3, CornerStyle::kSquare), 3);
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_TRUE(is_simple(*r));
  // The hem's allowance continues past (100, 0) by the next edge's width.
  bool found = false;
  for (Vec2 p : *r) found |= norm(p - Vec2{110, -10}) < 1e-6;
  EXPECT_TRUE(found);
}

TEST(CutOutline, ZeroWidthEdgesAreCutOnTheSeamLine) {
  const Polygon sq{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  auto r = cut_outline(polygon_edges(sq), {10, 0, 10, 10}, std::vector<CornerStyle>(4, CornerStyle::kMitre), 3);
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_NEAR(bounds(*r).max.x, 100, 1e-9);
}

TEST(CutOutline, RejectsAClockwiseSeamLine) {
  const Polygon cw{{0, 0}, {0, 100}, {100, 100}, {100, 0}};
  auto r = cut_outline(polygon_edges(cw), {10, 10, 10, 10}, std::vector<CornerStyle>(4, CornerStyle::kMitre), 3);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("counter-clockwise"), std::string::npos) << r.error().message;
}

TEST(CutOutline, RejectsMismatchedSizesAndNegativeWidths) {
  const Polygon sq{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  auto a = cut_outline(polygon_edges(sq), {10, 10}, std::vector<CornerStyle>(4, CornerStyle::kMitre), 3);
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("widths"), std::string::npos);
  auto b = cut_outline(polygon_edges(sq), {10, -1, 10, 10}, std::vector<CornerStyle>(4, CornerStyle::kMitre), 3);
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().message.find("edge 1"), std::string::npos) << b.error().message;
}

}  // namespace
}  // namespace tp::geometry
