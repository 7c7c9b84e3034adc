// geometry/sewing/internal/strain_blocks.h: the cloth's triangles (and bending stencils) split into
// blocks that share no vertex, so the strain and bending projections of one substep can run on
// several threads and still give the same positions to the bit for any thread count.
#pragma once

#include <vector>

#include "geometry/common/thread_pool.h"
#include "geometry/common/vec.h"
#include "geometry/sewing/internal/cloth_model.h"

namespace tp::geometry::internal {

/// One block: its triangles renumbered over its own vertices, which it projects in a copy of
/// their positions (a thread's writes then never share a cache line with another's).
struct StrainBlock {
  std::vector<int> vertices;            ///< the cloth's vertex of each local vertex, ascending
  std::vector<RestTriangle> triangles;  ///< local vertex indices, in the cloth's triangle order
  std::vector<double> inv_mass;         ///< per local vertex
  std::vector<Vec3> x_mm;               ///< per local vertex: the copy projected in
};

/// The triangles in rounds of blocks: the blocks of a round share no vertex (they run in
/// parallel), the rounds run one after the other, then the triangles left, in one thread.
struct StrainBlocks {
  std::vector<std::vector<StrainBlock>> rounds;
  std::vector<int> serial;  ///< ascending
};

/// Splits the triangles by recursive halving of their centroids at `x` along the longest side of
/// their box, `levels` times (2^levels blocks, whatever the thread count); the triangles with a
/// vertex in two blocks (bands along the cuts) are split again the same way in the next round
/// (up to `rounds`; on shirt_mean's drape the first round holds 86 % of the triangles, the next
/// two 4 %). Only which vertices the triangles share matters, so the plan stays valid however the
/// cloth moves; `inv_mass` must not change.
StrainBlocks plan_strain_blocks(const std::vector<RestTriangle>& triangles, const std::vector<double>& inv_mass,
                                const std::vector<Vec3>& x, int levels, int rounds);

/// Elements (by index) in rounds of blocks that share no vertex within a round, then the rest.
struct ElementRounds {
  std::vector<std::vector<std::vector<int>>> rounds;  ///< round, block: element indices, ascending
  std::vector<int> serial;                            ///< ascending
};

/// The bending stencils split as plan_strain_blocks splits triangles (by their four vertices'
/// centroid; a block's stencils share no vertex with another block's of the round).
ElementRounds plan_bend_blocks(const std::vector<BendStencil>& bends, const std::vector<Vec3>& x, int levels,
                               int rounds);

/// One strain pass (project_triangle on every triangle with `limit` and `stiffness`): each round's
/// blocks on `pool`, each in its triangles' order, then the serial triangles in theirs. The result
/// does not depend on the pool's size.
void project_strain_blocks(StrainBlocks& plan, const std::vector<RestTriangle>& triangles,
                           const std::vector<double>& inv_mass, double limit, double stiffness, ThreadPool& pool,
                           std::vector<Vec3>& x);

}  // namespace tp::geometry::internal
