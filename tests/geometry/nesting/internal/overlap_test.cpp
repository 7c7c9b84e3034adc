// tests/geometry/nesting/internal/overlap_test.cpp: the collision kernel (touching counts,
// containment found) and the pole overlap proxy.
#include "geometry/nesting/internal/overlap.h"

#include <gtest/gtest.h>

namespace tp::geometry::nesting {
namespace {

TEST(Overlap, TouchingCountsAndContainmentIsFound) {
  auto ref = [](const std::vector<Vec2>& p, Vec2 inner) {
    PolyRef r{p.data(), static_cast<int>(p.size()), {}, inner};
    for (Vec2 v : p) r.box.add(v);
    return r;
  };
  std::vector<int> ea, eb;
  const std::vector<Vec2> a{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const std::vector<Vec2> touching{{10, 0}, {20, 0}, {20, 10}, {10, 10}};
  const std::vector<Vec2> apart{{10.001, 0}, {20, 0}, {20, 10}, {10.001, 10}};
  const std::vector<Vec2> inside{{2, 2}, {4, 2}, {4, 4}, {2, 4}};
  const std::vector<Vec2> same_line{{5, 0}, {15, 0}, {15, 10}, {5, 10}};
  EXPECT_TRUE(polygons_collide(ref(a, {5, 5}), ref(touching, {15, 5}), ea, eb));
  EXPECT_FALSE(polygons_collide(ref(a, {5, 5}), ref(apart, {15, 5}), ea, eb));
  EXPECT_TRUE(polygons_collide(ref(a, {5, 5}), ref(inside, {3, 3}), ea, eb));
  EXPECT_TRUE(polygons_collide(ref(inside, {3, 3}), ref(a, {5, 5}), ea, eb));
  EXPECT_TRUE(polygons_collide(ref(a, {5, 5}), ref(same_line, {10, 5}), ea, eb));
  EXPECT_TRUE(polygons_collide(ref(a, {5, 5}), ref(a, {5, 5}), ea, eb)) << "a copy on top of itself";
}

TEST(Overlap, ProxyGrowsWithPenetration) {
  const std::vector<Circle> a{{{0, 0}, 5}}, b{{{0, 0}, 5}};
  PoleSoA soa;
  soa.assign(a);
  const double shallow = overlap_proxy(soa, b, {9, 0}, 0.1);
  const double deep = overlap_proxy(soa, b, {2, 0}, 0.1);
  const double apart = overlap_proxy(soa, b, {30, 0}, 0.1);
  EXPECT_GT(deep, shallow);
  EXPECT_GT(shallow, apart);
  EXPECT_GT(apart, 0);
  EXPECT_NEAR(deep, 3.14159265 * 8 * 5, 1e-3);
}

}  // namespace
}  // namespace tp::geometry::nesting
