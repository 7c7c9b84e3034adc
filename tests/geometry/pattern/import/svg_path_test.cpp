// tests/geometry/pattern/svg_path_test.cpp: SVG path data, arcs and transforms.
#include "geometry/pattern/import/svg_path.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tp::geometry {
namespace {

TEST(SvgPath, AbsoluteRelativeAndImplicitCommands) {
  auto r = parse_svg_path("M10,10 20,10 l0,10 h-5 v5 H0 V0 z m 5 5 L6 6");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  ASSERT_EQ(r->size(), 2u);
  const auto& a = (*r)[0];
  EXPECT_TRUE(a.closed);
  ASSERT_EQ(a.segments.size(), 7u);  // implicit L, l, h, v, H, V, closing line
  EXPECT_EQ(a.segments[0].to, (Vec2{20, 10}));
  EXPECT_EQ(a.segments[1].to, (Vec2{20, 20}));
  EXPECT_EQ(a.segments[2].to, (Vec2{15, 20}));
  EXPECT_EQ(a.segments[3].to, (Vec2{15, 25}));
  EXPECT_EQ(a.segments[6].to, (Vec2{10, 10}));
  // After z the pen is back at (10, 10); "m 5 5" is relative to it.
  EXPECT_EQ((*r)[1].start, (Vec2{15, 15}));
}

TEST(SvgPath, CompactNumbersAndSmoothCurves) {
  auto r = parse_svg_path("M0-1.5e1C.5.5 1-1 2,0S4,1 5,0Q6,1 7,0T9,0");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const auto& s = (*r)[0].segments;
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ((*r)[0].start, (Vec2{0, -15}));
  EXPECT_EQ(s[0].c1, (Vec2{0.5, 0.5}));
  EXPECT_EQ(s[0].c2, (Vec2{1, -1}));
  EXPECT_EQ(s[1].c1, (Vec2{3, 1}));  // reflection of (1, -1) about (2, 0)
  EXPECT_EQ(s[3].c1, (Vec2{8, -1}));  // reflection of (6, 1) about (7, 0)
}

TEST(SvgPath, ArcFlagsWithoutSeparators) {
  auto r = parse_svg_path("M0,0a10,10 0 0110,10");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const SvgSegment& a = (*r)[0].segments[0];
  EXPECT_EQ(a.kind, SvgSegment::Kind::kArc);
  EXPECT_FALSE(a.large_arc);
  EXPECT_TRUE(a.sweep);
  EXPECT_EQ(a.to, (Vec2{10, 10}));
}

TEST(SvgPath, ArcBecomesCubicsOnItsCircle) {
  SvgSegment a;
  a.kind = SvgSegment::Kind::kArc;
  a.from = {100, 0};
  a.to = {-100, 0};
  a.rx = a.ry = 100;
  a.sweep = true;
  auto cubics = svg_arc_to_cubics(a, 0.001);
  ASSERT_GE(cubics.size(), 2u);
  EXPECT_EQ(cubics.back()[2], (Vec2{-100, 0}));
  // Sample each cubic: every point within the tolerance of the circle, on the sweep side (y > 0).
  Vec2 p0 = a.from;
  for (const auto& c : cubics) {
    for (int i = 0; i <= 20; ++i) {
      double t = i / 20.0, u = 1 - t;
      Vec2 p = p0 * (u * u * u) + c[0] * (3 * u * u * t) + c[1] * (3 * u * t * t) + c[2] * (t * t * t);
      EXPECT_NEAR(norm(p), 100, 0.001);
      EXPECT_GE(p.y, -1e-9);
    }
    p0 = c[2];
  }
  // Radii too small for the chord are scaled up: a half circle of radius 100.
  a.rx = a.ry = 1;
  auto scaled = svg_arc_to_cubics(a, 0.01);
  EXPECT_NEAR(norm(scaled.front()[2]), 100, 0.01);
}

TEST(SvgPath, MalformedDataIsRejectedWithTheOffset) {
  for (const char* bad : {"L 1 2", "M 1", "M 0 0 X 1 1", "M 0 0 A 1 1 0 2 0 3 3", "M 0 0 z 1 2", "M 0 0 C 1 2 3"}) {
    auto r = parse_svg_path(bad);
    ASSERT_FALSE(r.has_value()) << bad;
    EXPECT_NE(r.error().message.find("at offset"), std::string::npos) << bad;
  }
  auto empty = parse_svg_path("  ");
  ASSERT_TRUE(empty.has_value());
  EXPECT_TRUE(empty->empty());
}

TEST(SvgTransform, ComposesLeftToRightAsSvgDoes) {
  auto t = parse_svg_transform("translate(10, 20) scale(2) rotate(90)");
  ASSERT_TRUE(t.has_value()) << t.error().what();
  Vec2 p = t->apply({1, 0});  // rotate -> (0, 1), scale -> (0, 2), translate -> (10, 22)
  EXPECT_NEAR(p.x, 10, 1e-12);
  EXPECT_NEAR(p.y, 22, 1e-12);
  auto m = parse_svg_transform("matrix(1 0 0 1 5 6) rotate(180 1 1)");
  ASSERT_TRUE(m.has_value());
  Vec2 q = m->apply({0, 0});  // rotating (0,0) about (1,1) by 180 -> (2,2), then +(5,6)
  EXPECT_NEAR(q.x, 7, 1e-12);
  EXPECT_NEAR(q.y, 8, 1e-12);
  EXPECT_FALSE(parse_svg_transform("spin(3)").has_value());
  EXPECT_FALSE(parse_svg_transform("translate(1,2,3)").has_value());
  EXPECT_FALSE(parse_svg_transform("scale(2").has_value());
}

}  // namespace
}  // namespace tp::geometry
