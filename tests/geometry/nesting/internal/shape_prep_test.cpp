// tests/geometry/nesting/internal/shape_prep_test.cpp: collision outlines: cleaning, growth by the
// clearance and outward-only simplification, checked with exact predicates.
#include "geometry/nesting/internal/shape_prep.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tp::geometry::nesting {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;

CGAL::Polygon_2<K> exact(const Polygon& p) {
  CGAL::Polygon_2<K> e;
  for (Vec2 v : p) e.push_back(K::Point_2(v.x, v.y));
  return e;
}

bool outside(const CGAL::Polygon_2<K>& poly, Vec2 v) {
  return poly.bounded_side(K::Point_2(v.x, v.y)) == CGAL::ON_UNBOUNDED_SIDE;
}

// A wobbly disc of radius ~100 with `n` vertices: many small reflex corners to simplify away.
Polygon wobbly(int n) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    const double r = 100 + 1.5 * std::sin(17 * a) + 0.7 * std::cos(5 * a);
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

TEST(ShapePrep, CleanDropsRepeatsAndCollinearPointsAndOrients) {
  auto c = clean_polygon({{0, 0}, {0, 4}, {0, 4}, {4, 4}, {4, 2}, {4, 0}, {0, 0}}, "square");
  ASSERT_TRUE(c) << c.error().what();
  EXPECT_EQ(c->size(), 4u);
  EXPECT_GT(signed_area(*c), 0) << "clockwise input comes out counter-clockwise";
  EXPECT_DOUBLE_EQ(signed_area(*c), 16);
}

TEST(ShapePrep, CleanRejectsWhatIsNotAPieceNamingIt) {
  auto bowtie = clean_polygon({{0, 0}, {4, 4}, {4, 0}, {0, 4}}, "piece 'yoke'");
  ASSERT_FALSE(bowtie);
  EXPECT_EQ(bowtie.error().code, ErrorCode::kInvalidPattern);
  EXPECT_NE(bowtie.error().message.find("piece 'yoke'"), std::string::npos);
  EXPECT_FALSE(clean_polygon({{0, 0}, {1, 1}, {2, 2}}, "line"));
  EXPECT_FALSE(clean_polygon({{0, 0}, {1, 0}}, "two points"));
  EXPECT_FALSE(clean_polygon({{0, 0}, {1, NAN}, {1, 1}}, "nan"));
}

TEST(ShapePrep, InflateCoversEveryPointWithinTheRadius) {
  const Polygon base = *clean_polygon({{0, 0}, {50, 0}, {50, 30}, {25, 10}, {0, 30}}, "notched");
  const double r = 2.0;
  const Polygon grown = inflate_polygon(base, r, 16);
  const auto e = exact(grown);
  ASSERT_TRUE(e.is_simple());
  for (size_t i = 0; i < base.size(); ++i) {
    const Vec2 a = base[i], b = base[(i + 1) % base.size()];
    for (int s = 0; s <= 10; ++s) {
      const Vec2 on = a + (b - a) * (s / 10.0);
      for (int k = 0; k < 24; ++k) {
        const double ang = 2 * std::numbers::pi * k / 24;
        EXPECT_FALSE(outside(e, on + Vec2{std::cos(ang), std::sin(ang)} * (r * 0.999999)));
      }
    }
  }
  // Not much more than the radius: the area grows by about perimeter * r.
  EXPECT_LT(signed_area(grown), signed_area(base) + 170 * r + 3.3 * r * r * 4);
}

TEST(ShapePrep, SimplifyNeverCutsIntoTheOutline) {
  const Polygon base = *clean_polygon(wobbly(400), "wobbly");
  const double budget = 0.01 * signed_area(base);
  const Polygon simple = simplify_outward(base, budget);
  EXPECT_LT(simple.size(), base.size() / 4) << "most small wobbles should go";
  const auto e = exact(simple);
  ASSERT_TRUE(e.is_simple());
  for (Vec2 v : base) EXPECT_FALSE(outside(e, v));
  EXPECT_LE(signed_area(simple), signed_area(base) + budget * (1 + 1e-9));
  EXPECT_GE(signed_area(simple), signed_area(base));
}

}  // namespace
}  // namespace tp::geometry::nesting
