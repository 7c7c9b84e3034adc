// tests/geometry/sewing/strain_blocks_test.cpp: the vertex-disjoint blocks the strain passes and
// the bending run in parallel: every triangle (stencil) once, no vertex in two blocks of a round,
// and a parallel pass equal to the same order in one thread, to the bit.
#include "geometry/sewing/internal/strain_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "geometry/sewing/internal/xpbd_solver.h"
#include "sheet_fixture.h"

namespace tp::geometry {
namespace {

// A 60 x 60 cell sheet of 5 mm cells, bent over a cylinder and stretched 10 % along x.
internal::ClothModel stretched_sheet() {
  Garment g;
  test_fixture::add_grid_piece(g, 60, 60, 5.0, [](int i, int j) {
    const double a = i * 5.0 * 1.1 / 300;
    return Vec3{300 * std::sin(a), 300 * std::cos(a), j * 5.0};
  });
  return internal::build_cloth_model(g, *cloth_material_preset("cotton-poplin"));
}

std::array<int, 3> sorted_corners(const std::vector<int>& vertices, const internal::RestTriangle& t) {
  std::array<int, 3> c{vertices[t.v[0]], vertices[t.v[1]], vertices[t.v[2]]};
  std::sort(c.begin(), c.end());
  return c;
}

TEST(StrainBlocks, EveryTriangleOnceAndNoVertexInTwoBlocksOfARound) {
  const internal::ClothModel cloth = stretched_sheet();
  const auto plan = internal::plan_strain_blocks(cloth.triangles, cloth.inv_mass, cloth.x_mm, 3, 3);
  std::set<std::array<int, 3>> all, seen;
  std::vector<int> identity(cloth.x_mm.size());
  for (size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<int>(i);
  for (const auto& t : cloth.triangles) all.insert(sorted_corners(identity, t));
  size_t in_blocks = 0;
  ASSERT_EQ(plan.rounds.size(), 3u);
  for (const auto& round : plan.rounds) {
    ASSERT_EQ(round.size(), 8u);
    std::vector<int> owner(cloth.x_mm.size(), -1);
    for (size_t b = 0; b < round.size(); ++b) {
      const internal::StrainBlock& blk = round[b];
      ASSERT_EQ(blk.inv_mass.size(), blk.vertices.size());
      for (size_t k = 0; k < blk.vertices.size(); ++k) {
        EXPECT_EQ(owner[blk.vertices[k]], -1) << "vertex " << blk.vertices[k] << " in two blocks";
        owner[blk.vertices[k]] = static_cast<int>(b);
        EXPECT_EQ(blk.inv_mass[k], cloth.inv_mass[blk.vertices[k]]);
      }
      for (const auto& t : blk.triangles) EXPECT_TRUE(seen.insert(sorted_corners(blk.vertices, t)).second);
      in_blocks += blk.triangles.size();
    }
  }
  for (int f : plan.serial) EXPECT_TRUE(seen.insert(sorted_corners(identity, cloth.triangles[f])).second);
  EXPECT_EQ(seen, all);
  // Measured: 6,264 of the 7,200 triangles in the rounds' blocks, 936 (13 %) left for one thread.
  std::printf("figure strain_blocks in_blocks=%zu serial=%zu of %zu\n", in_blocks, plan.serial.size(),
              cloth.triangles.size());
  EXPECT_LT(plan.serial.size(), cloth.triangles.size() / 5);
}

TEST(StrainBlocks, ParallelPassEqualsTheSameOrderInOneThreadToTheBit) {
  internal::ClothModel cloth = stretched_sheet();
  auto plan = internal::plan_strain_blocks(cloth.triangles, cloth.inv_mass, cloth.x_mm, 3, 3);
  // The reference: each round's blocks one after the other, then the serial triangles.
  std::vector<Vec3> ref = cloth.x_mm;
  for (const auto& round : plan.rounds)
    for (const auto& blk : round)
      for (const auto& lt : blk.triangles) {
        internal::RestTriangle t = lt;
        for (int& v : t.v) v = blk.vertices[v];
        internal::project_triangle(t, cloth.inv_mass, 0.03, 0.5, ref);
      }
  for (int f : plan.serial) internal::project_triangle(cloth.triangles[f], cloth.inv_mass, 0.03, 0.5, ref);
  for (int threads : {1, 2, 3}) {
    ThreadPool pool(threads, threads == 2 ? 300 : 0);
    std::vector<Vec3> x = cloth.x_mm;
    internal::project_strain_blocks(plan, cloth.triangles, cloth.inv_mass, 0.03, 0.5, pool, x);
    ASSERT_EQ(x.size(), ref.size());
    EXPECT_EQ(std::memcmp(x.data(), ref.data(), x.size() * sizeof(Vec3)), 0) << threads << " threads";
  }
  // The pass did its work: the 10 % stretch along x is pulled in.
  const Vec3 a = cloth.x_mm[0], b = cloth.x_mm[60];
  EXPECT_LT(norm(ref[60] - ref[0]), norm(b - a));
}

TEST(StrainBlocks, EveryBendStencilOnceAndNoVertexInTwoBlocksOfARound) {
  const internal::ClothModel cloth = stretched_sheet();
  ASSERT_GT(cloth.bends.size(), 10000u);
  const internal::ElementRounds plan = internal::plan_bend_blocks(cloth.bends, cloth.x_mm, 3, 3);
  std::vector<int> seen(cloth.bends.size(), 0);
  size_t in_blocks = 0;
  ASSERT_EQ(plan.rounds.size(), 3u);
  for (const auto& round : plan.rounds) {
    ASSERT_EQ(round.size(), 8u);
    std::vector<int> owner(cloth.x_mm.size(), -1);
    for (size_t b = 0; b < round.size(); ++b) {
      EXPECT_TRUE(std::is_sorted(round[b].begin(), round[b].end()));
      for (int k : round[b]) {
        ++seen[k];
        const internal::BendStencil& s = cloth.bends[k];
        for (int v : {s.a, s.b, s.c, s.d}) {
          EXPECT_TRUE(owner[v] == -1 || owner[v] == static_cast<int>(b)) << "vertex " << v << " in two blocks";
          owner[v] = static_cast<int>(b);
        }
      }
      in_blocks += round[b].size();
    }
  }
  EXPECT_TRUE(std::is_sorted(plan.serial.begin(), plan.serial.end()));
  for (int k : plan.serial) ++seen[k];
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(cloth.bends.size()));
  std::printf("figure bend_blocks in_blocks=%zu serial=%zu of %zu\n", in_blocks, plan.serial.size(),
              cloth.bends.size());
  EXPECT_LT(plan.serial.size(), cloth.bends.size() / 4);
}

}  // namespace
}  // namespace tp::geometry
