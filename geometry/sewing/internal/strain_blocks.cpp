// geometry/sewing/internal/strain_blocks.cpp: vertex-disjoint blocks of triangles (and of bending
// stencils) by recursive halving of their centroids, and the strain pass that runs them in parallel.
#include "geometry/sewing/internal/strain_blocks.h"

#include <algorithm>
#include <array>

#include "geometry/sewing/internal/xpbd_solver.h"

namespace tp::geometry::internal {
namespace {

constexpr int kSharedVertex = -2;
/// Fewer elements than this left are projected in one thread, not split again.
constexpr size_t kMinRoundElements = 256;

// Halves order[b, e) at the median of the centroids along their box's longest side, `levels`
// times, appending each leaf to `out`. Ties go by element index, so the split is one order.
void halve(std::vector<int>& order, size_t b, size_t e, int levels, const std::vector<Vec3>& centroid,
           std::vector<std::vector<int>>& out) {
  if (levels == 0 || e - b < 2) {
    out.emplace_back(order.begin() + static_cast<long>(b), order.begin() + static_cast<long>(e));
    return;
  }
  Vec3 lo = centroid[order[b]], hi = lo;
  for (size_t k = b; k < e; ++k) {
    const Vec3 c = centroid[order[k]];
    lo = Vec3{std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = Vec3{std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
  }
  const Vec3 size = hi - lo;
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  auto key = [&](int f) {
    const Vec3 c = centroid[f];
    return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
  };
  std::sort(order.begin() + static_cast<long>(b), order.begin() + static_cast<long>(e), [&](int p, int q) {
    const double kp = key(p), kq = key(q);
    return kp < kq || (kp == kq && p < q);
  });
  const size_t mid = b + (e - b) / 2;
  halve(order, b, mid, levels - 1, centroid, out);
  halve(order, mid, e, levels - 1, centroid, out);
}

// Splits elements (each its vertices) into rounds of vertex-disjoint blocks by halving their
// centroids at `x` (plan_strain_blocks' documentation); each block's elements ascending.
template <size_t K>
ElementRounds split_rounds(const std::vector<std::array<int, K>>& elements, const std::vector<Vec3>& x, int levels,
                           int rounds) {
  ElementRounds out;
  const int ne = static_cast<int>(elements.size());
  std::vector<Vec3> centroid(ne);
  for (int f = 0; f < ne; ++f) {
    Vec3 c{};
    for (int v : elements[f]) c += x[v];
    centroid[f] = c / static_cast<double>(K);
  }
  std::vector<int> left(ne);
  for (int f = 0; f < ne; ++f) left[f] = f;
  std::vector<int> vertex_block(x.size()), element_block(ne);
  for (int round = 0; round < rounds && left.size() >= kMinRoundElements; ++round) {
    std::vector<int> order = left;
    std::vector<std::vector<int>> leaves;
    halve(order, 0, order.size(), std::max(levels, 0), centroid, leaves);
    // Each vertex's block, or kSharedVertex once elements of two blocks use it.
    for (int f : left)
      for (int v : elements[f]) vertex_block[v] = -1;
    for (size_t b = 0; b < leaves.size(); ++b)
      for (int f : leaves[b]) {
        element_block[f] = static_cast<int>(b);
        for (int v : elements[f]) {
          int& vb = vertex_block[v];
          vb = vb == -1 || vb == static_cast<int>(b) ? static_cast<int>(b) : kSharedVertex;
        }
      }
    std::vector<std::vector<int>>& blocks = out.rounds.emplace_back(leaves.size());
    std::vector<int> shared;
    for (int f : left) {
      const int b = element_block[f];
      const auto& vs = elements[f];
      if (std::all_of(vs.begin(), vs.end(), [&](int v) { return vertex_block[v] == b; }))
        blocks[b].push_back(f);
      else
        shared.push_back(f);
    }
    left = std::move(shared);
  }
  out.serial = std::move(left);
  return out;
}

}  // namespace

StrainBlocks plan_strain_blocks(const std::vector<RestTriangle>& triangles, const std::vector<double>& inv_mass,
                                const std::vector<Vec3>& x, int levels, int rounds) {
  std::vector<std::array<int, 3>> corners(triangles.size());
  for (size_t f = 0; f < triangles.size(); ++f) corners[f] = triangles[f].v;
  const ElementRounds split = split_rounds(corners, x, levels, rounds);
  StrainBlocks plan;
  std::vector<int> local(x.size(), -1);
  for (const auto& round : split.rounds) {
    std::vector<StrainBlock>& blocks = plan.rounds.emplace_back(round.size());
    for (size_t b = 0; b < round.size(); ++b) {
      StrainBlock& blk = blocks[b];
      for (int f : round[b]) blk.triangles.push_back(triangles[f]);
      for (const RestTriangle& t : blk.triangles)
        for (int v : t.v) blk.vertices.push_back(v);
      std::sort(blk.vertices.begin(), blk.vertices.end());
      blk.vertices.erase(std::unique(blk.vertices.begin(), blk.vertices.end()), blk.vertices.end());
      for (size_t k = 0; k < blk.vertices.size(); ++k) local[blk.vertices[k]] = static_cast<int>(k);
      for (RestTriangle& t : blk.triangles)
        for (int& v : t.v) v = local[v];
      blk.inv_mass.resize(blk.vertices.size());
      for (size_t k = 0; k < blk.vertices.size(); ++k) blk.inv_mass[k] = inv_mass[blk.vertices[k]];
      blk.x_mm.resize(blk.vertices.size());
    }
  }
  plan.serial = split.serial;
  return plan;
}

ElementRounds plan_bend_blocks(const std::vector<BendStencil>& bends, const std::vector<Vec3>& x, int levels,
                               int rounds) {
  std::vector<std::array<int, 4>> stencils(bends.size());
  for (size_t k = 0; k < bends.size(); ++k) stencils[k] = {bends[k].a, bends[k].b, bends[k].c, bends[k].d};
  return split_rounds(stencils, x, levels, rounds);
}

void project_strain_blocks(StrainBlocks& plan, const std::vector<RestTriangle>& triangles,
                           const std::vector<double>& inv_mass, double limit, double stiffness, ThreadPool& pool,
                           std::vector<Vec3>& x) {
  for (std::vector<StrainBlock>& blocks : plan.rounds)
    pool.parallel_for(static_cast<int>(blocks.size()), [&](int b, int) {
      StrainBlock& blk = blocks[b];
      const size_t nv = blk.vertices.size();
      for (size_t k = 0; k < nv; ++k) blk.x_mm[k] = x[blk.vertices[k]];
      for (const RestTriangle& t : blk.triangles) project_triangle(t, blk.inv_mass, limit, stiffness, blk.x_mm);
      for (size_t k = 0; k < nv; ++k) x[blk.vertices[k]] = blk.x_mm[k];
    });
  for (int f : plan.serial) project_triangle(triangles[f], inv_mass, limit, stiffness, x);
}

}  // namespace tp::geometry::internal
