// geometry/sewing/internal/xpbd_sewing.cpp: the unsewn pieces as one XPBD cloth whose stitches
// close at a fixed speed.
#include "geometry/sewing/internal/xpbd_sewing.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "geometry/garment/garment.h"
#include "geometry/sewing/internal/cloth_model.h"
#include "geometry/sewing/internal/xpbd_solver.h"

namespace tp::geometry::internal {
namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The solver's settings while sewing: no weight, no friction (seams slide over the body while
// they close), moves within 0.15 of the layer thickness per substep.
XpbdParams sewing_steps(const XpbdSewParams& p) {
  XpbdParams xp;
  xp.duration_s = p.duration_s;
  xp.gravity_mm_s2 = 0;
  xp.damping_per_s = p.damping_per_s;
  xp.body_thickness_mm = p.clearance_mm;
  xp.self_thickness_mm = p.self_thickness_mm;
  xp.max_move_mm = 0.15 * p.self_thickness_mm;
  xp.stretch_limit = p.material.stretch_limit;
  xp.stretch_stiffness = p.material.stretch_stiffness;
  xp.friction = 0;
  xp.threads = p.threads;
  return xp;
}

}  // namespace

Result<XpbdSewStats> sew_pieces_xpbd(const PatternMesh& meshes, const std::vector<int>& offset,
                                     const std::vector<std::array<int, 2>>& stitches,
                                     const std::vector<int>& pair_stitch, const BodySdf& body, const XpbdSewParams& p,
                                     std::vector<Vec3>& x_mm, const CancelToken* cancel) {
  // The pieces as a garment whose seams are still open: each piece its own vertices.
  Garment open;
  open.vertices_mm = x_mm;
  for (size_t pi = 0; pi < meshes.pieces.size(); ++pi) {
    GarmentPiece gp;
    gp.piece = static_cast<int>(pi);
    gp.mesh = meshes.pieces[pi];
    gp.vertex_3d.resize(gp.mesh.vertices_mm.size());
    std::iota(gp.vertex_3d.begin(), gp.vertex_3d.end(), offset[pi]);
    open.pieces.push_back(std::move(gp));
  }
  ClothModel cloth = build_cloth_model(open, p.material);
  cloth.stitches = stitches;
  for (const GatheredSide& side : p.gathered) {
    std::vector<int> seam = side.vertices;
    std::sort(seam.begin(), seam.end());
    mark_gathered(cloth.triangles, seam, side.ratio * kGatherSlack);
  }
  // Weld groups: the lowest vertex of each transitively stitched set.
  const int n = static_cast<int>(x_mm.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& s : stitches) {
    const int a = find_root(parent, s[0]), b = find_root(parent, s[1]);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  cloth.weld_group.resize(n);
  for (int i = 0; i < n; ++i) cloth.weld_group[i] = find_root(parent, i);
  // Seam neighbourhoods: per weld group, the groups of all its members' mesh neighbours (the
  // sewn vertex's 1-ring on both sides of the seam), given to every stitched member. With each
  // vertex's own neighbours only, a seam side that started overlapping its partner's piece hit
  // the partner's second row and stayed open (the blouse's left side seam, 49 mm).
  cloth.seam_near.assign(n, {});
  std::vector<uint8_t> stitched(n, 0);
  for (const auto& s : stitches) stitched[s[0]] = stitched[s[1]] = 1;
  for (int i = 0; i < n; ++i)
    if (stitched[i]) cloth.seam_near[cloth.weld_group[i]].push_back(cloth.weld_group[i]);
  for (const auto& e : cloth.edges) {
    if (stitched[e[0]]) cloth.seam_near[cloth.weld_group[e[0]]].push_back(cloth.weld_group[e[1]]);
    if (stitched[e[1]]) cloth.seam_near[cloth.weld_group[e[1]]].push_back(cloth.weld_group[e[0]]);
  }
  for (auto& list : cloth.seam_near) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for (int i = 0; i < n; ++i)
    if (stitched[i] && cloth.weld_group[i] != i) cloth.seam_near[i] = cloth.seam_near[cloth.weld_group[i]];
  // Seam zones: every vertex of a stitch side's piece closer (2D) to the side's nearest stitched
  // vertex than that pair starts apart.
  if (pair_stitch.size() == stitches.size()) {
    cloth.seam_zones.assign(n, {});
    std::vector<std::vector<int>> stitch_pairs;
    for (size_t k = 0; k < stitches.size(); ++k) {
      if (pair_stitch[k] >= static_cast<int>(stitch_pairs.size())) stitch_pairs.resize(pair_stitch[k] + 1);
      stitch_pairs[pair_stitch[k]].push_back(static_cast<int>(k));
    }
    auto chart = [&](int v) {
      const int pc = cloth.vertex_piece[v];
      return meshes.pieces[pc].vertices_mm[v - offset[pc]];
    };
    for (size_t s = 0; s < stitch_pairs.size(); ++s) {
      if (stitch_pairs[s].empty()) continue;
      for (int side = 0; side < 2; ++side) {
        const int pc = cloth.vertex_piece[stitches[stitch_pairs[s][0]][side]];
        for (int u = offset[pc]; u < offset[pc + 1]; ++u) {
          int best = -1;
          double best_d = 1e300;
          for (int k : stitch_pairs[s]) {
            const double d = norm(chart(u) - chart(stitches[k][side]));
            if (d < best_d) best_d = d, best = k;
          }
          const double start_gap = norm(x_mm[stitches[best][0]] - x_mm[stitches[best][1]]);
          if (best_d < start_gap) cloth.seam_zones[u].push_back({best, static_cast<int>(2 * s) + side, best_d});
        }
      }
    }
  }

  XpbdParams xp = sewing_steps(p);
  xp.stitch_close_mm_s = p.close_mm_s;
  xp.stitch_done_mm = p.done_gap_mm;
  xp.stitch_stall_s = p.stall_s;
  xp.on_progress = p.on_progress;
  auto r = run_xpbd(cloth, body, xp, cancel);
  if (!r) return fail(r.error().with_context("XPBD sewing"));
  x_mm = std::move(cloth.x_mm);
  return XpbdSewStats{
      .substeps = r->substeps, .simulated_s = r->simulated_s, .stitch_gap_max_mm = r->stitch_gap_max_mm};
}

Result<XpbdSewStats> settle_fine_garment(Garment& g, const BodySdf& body, const SewOptions& o,
                                         const CancelToken* cancel) {
  XpbdSewParams p;
  p.duration_s = o.xpbd_relax_s;
  p.clearance_mm = o.clearance_mm;
  p.self_thickness_mm = o.xpbd_self_thickness_mm;
  p.threads = o.threads;
  ClothModel cloth = build_cloth_model(g, p.material);
  auto r = run_xpbd(cloth, body, sewing_steps(p), cancel);
  if (!r) return fail(r.error());
  g.vertices_mm = std::move(cloth.x_mm);
  return XpbdSewStats{.substeps = r->substeps, .simulated_s = r->simulated_s, .stitch_gap_max_mm = 0};
}

}  // namespace tp::geometry::internal
