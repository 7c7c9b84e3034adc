// geometry/garment/sew_garment.cpp: seams drawn together, merged, and the garment relaxed on the body.
#include "geometry/garment/sew_garment.h"

#include <chrono>
#include <cmath>
#include <numeric>

#include "geometry/garment/initial_placement.h"
#include "geometry/garment/internal/arap_solver.h"

namespace tp::geometry {
namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Seam spring stiffness ramp of phase A: soft first so pieces swing into place, then stiff.
constexpr double kSpringWeights[] = {0.05, 0.3, 2.0, 20.0};

}  // namespace

Result<Garment> sew_garment(const Pattern& pattern, const BodySdf& body, const SewOptions& options, SewStats* stats,
                            const CancelToken* cancel) {
  auto meshes = mesh_pattern(pattern, TriangulateOptions{.target_edge_mm = options.target_edge_mm});
  if (!meshes) return std::unexpected(meshes.error());
  return sew_garment(pattern, *meshes, body, options, stats, cancel);
}

Result<Garment> sew_garment(const Pattern& pattern, const PatternMesh& meshes, const BodySdf& body,
                            const SewOptions& options, SewStats* stats, const CancelToken* cancel) {
  const auto t0 = std::chrono::steady_clock::now();
  if (meshes.pieces.size() != pattern.pieces.size() || meshes.stitch_vertices.size() != pattern.stitches.size())
    return fail(ErrorCode::kInvalidArgument, "pattern '" + pattern.name + "': mesh does not match the pattern");
  SewStats local_stats;
  SewStats& st = stats ? *stats : local_stats;

  // Phase A cloth: every piece's vertices separate, stitched pairs joined by springs.
  internal::ClothMesh cloth;
  std::vector<int> offset(pattern.pieces.size() + 1, 0);
  for (size_t p = 0; p < pattern.pieces.size(); ++p)
    offset[p + 1] = offset[p] + static_cast<int>(meshes.pieces[p].vertices_mm.size());
  auto start = initial_placement(pattern, meshes, body);
  for (size_t p = 0; p < pattern.pieces.size(); ++p) {
    const PieceMesh& m = meshes.pieces[p];
    cloth.x_mm.insert(cloth.x_mm.end(), start[p].begin(), start[p].end());
    for (const auto& t : m.triangles) {
      cloth.triangles.push_back({t[0] + offset[p], t[1] + offset[p], t[2] + offset[p]});
      cloth.rest_mm.push_back({m.vertices_mm[t[0]], m.vertices_mm[t[1]], m.vertices_mm[t[2]]});
    }
  }
  for (size_t s = 0; s < pattern.stitches.size(); ++s)
    for (const auto& pr : meshes.stitch_vertices[s])
      cloth.springs.push_back({pr[0] + offset[pattern.stitches[s].a.piece], pr[1] + offset[pattern.stitches[s].b.piece]});

  internal::ClothParams params;
  params.clearance_mm = options.clearance_mm;
  params.threads = options.threads;
  params.gravity_per_mm = 0;
  params.tolerance_mm = 0;
  const int steps = static_cast<int>(std::size(kSpringWeights));
  for (int k = 0; k < steps && !cloth.springs.empty(); ++k) {
    params.spring_weight = kSpringWeights[k];
    params.iterations = options.sewing_iterations / steps;
    auto r = internal::relax_cloth(cloth, body, params, cancel);
    if (!r) return std::unexpected(r.error().with_context("pattern '" + pattern.name + "': sewing"));
    st.sewing_iterations += r->iterations;
  }

  // Merge: every stitched pair (transitively) becomes one 3D vertex at the pair's mean.
  std::vector<int> parent(cloth.x_mm.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& s : cloth.springs) parent[find_root(parent, s[0])] = find_root(parent, s[1]);
  std::vector<int> merged_id(cloth.x_mm.size(), -1);
  internal::ClothMesh merged;
  std::vector<int> members;
  for (size_t i = 0; i < cloth.x_mm.size(); ++i) {
    int r = find_root(parent, static_cast<int>(i));
    if (merged_id[r] < 0) {
      merged_id[r] = static_cast<int>(merged.x_mm.size());
      merged.x_mm.push_back({});
      members.push_back(0);
    }
    merged_id[i] = merged_id[r];
    merged.x_mm[merged_id[i]] += cloth.x_mm[i];
    ++members[merged_id[i]];
  }
  for (size_t v = 0; v < merged.x_mm.size(); ++v) merged.x_mm[v] = merged.x_mm[v] / members[v];
  int degenerate = 0;
  for (size_t f = 0; f < cloth.triangles.size(); ++f) {
    const auto& t = cloth.triangles[f];
    std::array<int, 3> m{merged_id[t[0]], merged_id[t[1]], merged_id[t[2]]};
    if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2]) { ++degenerate; continue; }
    merged.triangles.push_back(m);
    merged.rest_mm.push_back(cloth.rest_mm[f]);
  }
  st.collapsed_triangles = degenerate;

  // Phase B: relax the sewn garment under gravity until it settles.
  params.spring_weight = 0;
  params.gravity_per_mm = options.gravity_per_mm;
  params.iterations = options.relax_iterations;
  params.tolerance_mm = options.tolerance_mm;
  auto r = internal::relax_cloth(merged, body, params, cancel);
  if (!r) return std::unexpected(r.error().with_context("pattern '" + pattern.name + "': relaxing"));
  st.relax_iterations = r->iterations;
  st.last_move_mm = r->last_move_mm;
  st.contacts = r->contacts;

  Garment g;
  g.vertices_mm = std::move(merged.x_mm);
  for (size_t p = 0; p < pattern.pieces.size(); ++p) {
    GarmentPiece gp;
    gp.piece = static_cast<int>(p);
    gp.mesh = meshes.pieces[p];
    for (int v = offset[p]; v < offset[p + 1]; ++v) gp.vertex_3d.push_back(merged_id[v]);
    g.pieces.push_back(std::move(gp));
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return g;
}

}  // namespace tp::geometry
