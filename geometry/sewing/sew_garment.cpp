// geometry/sewing/sew_garment.cpp: seams drawn together, merged, and the garment relaxed on the body.
#include "geometry/sewing/sew_garment.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "geometry/common/tolerances.h"
#include "geometry/garment/fit_checks.h"
#include "geometry/garment/initial_placement.h"
#include "geometry/sewing/internal/arap_solver.h"
#include "geometry/sewing/internal/cloth_model.h"
#include "geometry/sewing/internal/xpbd_sewing.h"

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

namespace {

// A cloth whose seams are merged: one vertex per sewn point, and the chart-to-cloth map.
struct MergedCloth {
  internal::ClothMesh cloth;
  std::vector<int> merged_id;  ///< per chart vertex (global numbering)
  int collapsed = 0;
};

MergedCloth merge_seams(const internal::ClothMesh& cloth) {
  std::vector<int> parent(cloth.x_mm.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& s : cloth.springs) parent[find_root(parent, s[0])] = find_root(parent, s[1]);
  MergedCloth m;
  m.merged_id.assign(cloth.x_mm.size(), -1);
  std::vector<int> members;
  for (size_t i = 0; i < cloth.x_mm.size(); ++i) {
    int r = find_root(parent, static_cast<int>(i));
    if (m.merged_id[r] < 0) {
      m.merged_id[r] = static_cast<int>(m.cloth.x_mm.size());
      m.cloth.x_mm.push_back({});
      members.push_back(0);
    }
    m.merged_id[i] = m.merged_id[r];
    m.cloth.x_mm[m.merged_id[i]] += cloth.x_mm[i];
    ++members[m.merged_id[i]];
  }
  for (size_t v = 0; v < m.cloth.x_mm.size(); ++v) m.cloth.x_mm[v] = m.cloth.x_mm[v] / members[v];
  for (size_t f = 0; f < cloth.triangles.size(); ++f) {
    const auto& t = cloth.triangles[f];
    std::array<int, 3> q{m.merged_id[t[0]], m.merged_id[t[1]], m.merged_id[t[2]]};
    if (q[0] == q[1] || q[1] == q[2] || q[0] == q[2]) { ++m.collapsed; continue; }
    m.cloth.triangles.push_back(q);
    m.cloth.rest_mm.push_back(cloth.rest_mm[f]);
  }
  return m;
}

// 3D positions for the vertices of `fine` (one piece's 2D mesh), interpolated linearly in the
// triangle of the coarse chart that contains each vertex (or the nearest one).
std::vector<Vec3> interpolate_chart(const GarmentPiece& coarse, const std::vector<Vec3>& coarse_3d, const PieceMesh& fine) {
  const auto& cv = coarse.mesh.vertices_mm;
  std::vector<Vec3> out;
  out.reserve(fine.vertices_mm.size());
  for (Vec2 p : fine.vertices_mm) {
    double best = 1e300;
    Vec3 pos{};
    for (const auto& t : coarse.mesh.triangles) {
      Vec2 a = cv[t[0]], b = cv[t[1]], c = cv[t[2]];
      double det = cross(b - a, c - a);
      if (std::abs(det) < kParallelDeterminant) continue;
      double l1 = cross(p - a, c - a) / det, l2 = cross(b - a, p - a) / det, l0 = 1 - l1 - l2;
      // Outside distance in barycentric terms: 0 inside the triangle.
      double out_by = std::max({-l0, -l1, -l2, 0.0});
      if (out_by < best) {
        best = out_by;
        l0 = std::max(l0, 0.0), l1 = std::max(l1, 0.0), l2 = std::max(l2, 0.0);
        double sum = l0 + l1 + l2;
        pos = (coarse_3d[coarse.vertex_3d[t[0]]] * l0 + coarse_3d[coarse.vertex_3d[t[1]]] * l1 +
               coarse_3d[coarse.vertex_3d[t[2]]] * l2) / sum;
        if (best == 0) break;
      }
    }
    out.push_back(pos);
  }
  return out;
}

// One stitch's segments between consecutive sewn vertex pairs: each side's pattern length, and
// whether the stitch is plain (its sides' lengths agree within kPlainSeamSegment; eased and
// gathered seams have no single rest length).
struct StitchSegments {
  std::vector<double> la, lb;
  bool plain = false;
};

StitchSegments stitch_segments(const Pattern& pattern, const PatternMesh& meshes, size_t s) {
  const auto& pairs = meshes.stitch_vertices[s];
  const int pa = pattern.stitches[s].a.piece, pb = pattern.stitches[s].b.piece;
  StitchSegments out;
  double total_a = 0, total_b = 0;
  for (size_t k = 0; k + 1 < pairs.size(); ++k) {
    out.la.push_back(norm(meshes.pieces[pa].vertices_mm[pairs[k + 1][0]] - meshes.pieces[pa].vertices_mm[pairs[k][0]]));
    out.lb.push_back(norm(meshes.pieces[pb].vertices_mm[pairs[k + 1][1]] - meshes.pieces[pb].vertices_mm[pairs[k][1]]));
    total_a += out.la.back(), total_b += out.lb.back();
  }
  out.plain = internal::plain_seam_lengths(total_a, total_b);
  return out;
}

// The longer sides of the stitches that are not plain (eased or gathered), for XPBD sewing.
std::vector<internal::GatheredSide> gathered_sides(const Pattern& pattern, const PatternMesh& meshes,
                                                   const std::vector<int>& offset) {
  std::vector<internal::GatheredSide> out;
  for (size_t s = 0; s < pattern.stitches.size(); ++s) {
    const StitchSegments seg = stitch_segments(pattern, meshes, s);
    if (seg.plain) continue;
    double total_a = 0, total_b = 0;
    for (double l : seg.la) total_a += l;
    for (double l : seg.lb) total_b += l;
    const int side = total_a >= total_b ? 0 : 1;
    internal::GatheredSide g;
    g.piece = side == 0 ? pattern.stitches[s].a.piece : pattern.stitches[s].b.piece;
    g.ratio = std::min(total_a, total_b) / std::max(total_a, total_b);
    for (const auto& pr : meshes.stitch_vertices[s]) g.vertices.push_back(pr[side] + offset[g.piece]);
    out.push_back(std::move(g));
  }
  return out;
}

// The garment of the merged cloth: every piece's chart and its vertices' merged ids.
Garment finish_garment(const Pattern& pattern, const PatternMesh& meshes, const std::vector<int>& offset,
                       MergedCloth& mc, SewStats& st, std::chrono::steady_clock::time_point t0) {
  Garment g;
  g.vertices_mm = std::move(mc.cloth.x_mm);
  for (size_t p = 0; p < pattern.pieces.size(); ++p) {
    GarmentPiece gp;
    gp.piece = static_cast<int>(p);
    gp.mesh = meshes.pieces[p];
    for (int v = offset[p]; v < offset[p + 1]; ++v) gp.vertex_3d.push_back(mc.merged_id[v]);
    g.pieces.push_back(std::move(gp));
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return g;
}

}  // namespace

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
  for (size_t p = 0; p < pattern.pieces.size(); ++p) {
    const PieceMesh& m = meshes.pieces[p];
    for (const auto& t : m.triangles) {
      cloth.triangles.push_back({t[0] + offset[p], t[1] + offset[p], t[2] + offset[p]});
      cloth.rest_mm.push_back({m.vertices_mm[t[0]], m.vertices_mm[t[1]], m.vertices_mm[t[2]]});
    }
  }
  std::vector<int> spring_stitch;  // per spring, its stitch
  for (size_t s = 0; s < pattern.stitches.size(); ++s)
    for (const auto& pr : meshes.stitch_vertices[s]) {
      cloth.springs.push_back({pr[0] + offset[pattern.stitches[s].a.piece], pr[1] + offset[pattern.stitches[s].b.piece]});
      spring_stitch.push_back(static_cast<int>(s));
    }

  internal::ClothParams params;
  params.clearance_mm = options.clearance_mm;
  params.threads = options.threads;
  // Progress over the iterations planned for both phases (the coarse level, if any, reports its own).
  int iterations_done = 0;
  const int iterations_planned = std::max(1, options.sewing_iterations + options.relax_iterations);
  if (options.on_progress)
    params.on_iteration = [&] { options.on_progress(std::min(1.0, ++iterations_done / double(iterations_planned))); };
  // Two levels by default for XPBD sewing (a substep costs in proportion to the vertices while
  // the substeps needed do not depend on them), one for ARAP (whose coarse level tangled). A coarse
  // level with edges over kMaxCoarseEdge_mm cuts across the body's curves: GarmentCode's hoody_mean
  // at the studio's 25 mm edge ended with 7 vertices inside mean_female from a 50 mm coarse level,
  // and none sewn on one level (shirt_mean: 52 and 0), so the coarse edge is at most that, and a
  // fine mesh that coarse sews on one.
  const double coarse_factor = options.coarse_factor >= 0 ? options.coarse_factor
                               : options.solver == SewSolver::kXpbd
                                   ? std::min(2.0, kMaxCoarseEdge_mm / options.target_edge_mm)
                                   : 0.0;
  const bool two_level = coarse_factor >= 1.5;
  st.levels = two_level ? 2 : 1;
  if (two_level) {
    // Coarse level: the whole sewing on a coarser mesh, then its shape carried over.
    SewOptions coarse_opt = options;
    coarse_opt.on_progress = {};  // the fine level reports; the coarse run is its first part
    coarse_opt.coarse_factor = 0;
    // A default coarse level that left a seam open or passes through itself (a mesh too coarse
    // for a narrow place: js_mean_all's crotch at 36 mm edges, 2.4 mm open; at 32 mm, 11
    // intersecting pairs, none at 31.8 mm) is not carried over: it is sewn once more on a mesh
    // kCoarseRetryFactor as coarse (not below 1.5 x the fine edge), then on one level. Whether a
    // coarse mesh crosses itself in such a place turns on its triangulation, and a coarse level
    // costs a fraction of one level.
    const bool by_default = options.coarse_factor < 0;  // an asked-for coarse level is kept as sewn
    std::vector<double> factors{coarse_factor};
    const double retry = std::max(1.5, coarse_factor * kCoarseRetryFactor);
    if (by_default && retry < coarse_factor) factors.push_back(retry);
    SewStats coarse_stats;
    Result<Garment> coarse = fail(ErrorCode::kSewing, "no coarse level");
    double coarse_gap = 0;
    int coarse_crossings = 0;
    bool coarse_ok = false;
    for (size_t attempt = 0; attempt < factors.size() && !coarse_ok; ++attempt) {
      coarse_opt.target_edge_mm = options.target_edge_mm * factors[attempt];
      coarse_stats = SewStats{};
      coarse = sew_garment(pattern, body, coarse_opt, &coarse_stats, cancel);
      if (!coarse) return fail(coarse.error());
      coarse_gap = 0;
      for (const auto& gaps : coarse_stats.stitch_gap_mm)
        for (double g : gaps) coarse_gap = std::max(coarse_gap, g);
      coarse_crossings = by_default ? count_self_intersections(*coarse) : 0;
      coarse_ok = !by_default || (coarse_gap <= kCoarseFallbackGap * options.xpbd_done_gap_mm && coarse_crossings == 0);
      if (!coarse_ok) st.coarse_discarded = static_cast<int>(attempt) + 1;
    }
    if (!coarse_ok) {
      const int discarded = st.coarse_discarded;
      SewOptions one_level = options;
      one_level.coarse_factor = 0;
      auto g = sew_garment(pattern, meshes, body, one_level, stats, cancel);
      if (stats) {
        stats->coarse_fallback_gap_mm = coarse_gap;
        stats->coarse_fallback_self_intersections = coarse_crossings;
        stats->coarse_discarded = discarded;
        stats->coarse_edge_mm = 0;
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      }
      return g;
    }
    st.coarse_edge_mm = coarse_opt.target_edge_mm;
    st.sewing_iterations = coarse_stats.sewing_iterations;
    st.stitch_gap_mm = std::move(coarse_stats.stitch_gap_mm);
    for (size_t p = 0; p < pattern.pieces.size(); ++p) {
      auto pos = interpolate_chart(coarse->pieces[p], coarse->vertices_mm, meshes.pieces[p]);
      cloth.x_mm.insert(cloth.x_mm.end(), pos.begin(), pos.end());
    }
  } else if (options.solver == SewSolver::kXpbd) {
    auto start = initial_placement(pattern, meshes, body);
    for (auto& piece_start : start) cloth.x_mm.insert(cloth.x_mm.end(), piece_start.begin(), piece_start.end());
    internal::XpbdSewParams xp;
    xp.close_mm_s = options.xpbd_close_mm_s;
    xp.done_gap_mm = options.xpbd_done_gap_mm;
    xp.duration_s = options.xpbd_duration_s;
    xp.stall_s = options.xpbd_stall_s;
    xp.clearance_mm = options.clearance_mm;
    xp.self_thickness_mm = options.xpbd_self_thickness_mm;
    xp.threads = options.threads;
    if (options.on_progress) xp.on_progress = options.on_progress;
    xp.gathered = gathered_sides(pattern, meshes, offset);
    auto r = internal::sew_pieces_xpbd(meshes, offset, cloth.springs, spring_stitch, body, xp, cloth.x_mm, cancel);
    if (!r) return fail(r.error().with_context("pattern '" + pattern.name + "': sewing"));
    st.sewing_iterations = r->substeps;
  } else {
    auto start = initial_placement(pattern, meshes, body);
    for (auto& piece_start : start) cloth.x_mm.insert(cloth.x_mm.end(), piece_start.begin(), piece_start.end());
    params.gravity_per_mm = 0;
    params.tolerance_mm = 0;
    const int steps = static_cast<int>(std::size(kSpringWeights));
    for (int k = 0; k < steps && !cloth.springs.empty(); ++k) {
      params.spring_weight = kSpringWeights[k];
      params.iterations = options.sewing_iterations / steps;
      auto r = internal::relax_cloth(cloth, body, params, cancel);
      if (!r) return fail(r.error().with_context("pattern '" + pattern.name + "': sewing"));
      st.sewing_iterations += r->iterations;
    }
  }

  // How far apart each stitch's two sides ended (the fit checks' stitch gap), before merging
  // hides it. With two levels the fine start is already merged: the coarse level's gaps stand.
  if (!two_level) {
    st.stitch_gap_mm.assign(pattern.stitches.size(), {});
    for (size_t s = 0; s < pattern.stitches.size(); ++s)
      for (const auto& pr : meshes.stitch_vertices[s])
        st.stitch_gap_mm[s].push_back(norm(cloth.x_mm[pr[0] + offset[pattern.stitches[s].a.piece]] -
                                           cloth.x_mm[pr[1] + offset[pattern.stitches[s].b.piece]]));
  }

  // Merge: every stitched pair (transitively) becomes one 3D vertex at the pair's mean.
  MergedCloth mc = merge_seams(cloth);
  internal::ClothMesh& merged = mc.cloth;
  st.collapsed_triangles = mc.collapsed;

  // Seam segments keep their pattern length once sewn (the stitching does not stretch): each
  // consecutive pair of seam vertices becomes a rest-length edge, its length the mean of the two
  // pieces' 2D lengths. Eased or gathered seams (the two sides' lengths differ by more than
  // kPlainSeamSegment) have no single rest length and are left to the membrane.
  for (size_t s = 0; s < pattern.stitches.size(); ++s) {
    const StitchSegments seg = stitch_segments(pattern, meshes, s);
    if (!seg.plain) continue;
    const auto& pairs = meshes.stitch_vertices[s];
    const int pa = pattern.stitches[s].a.piece;
    for (size_t k = 0; k + 1 < pairs.size(); ++k) {
      const int i = mc.merged_id[pairs[k][0] + offset[pa]], j = mc.merged_id[pairs[k + 1][0] + offset[pa]];
      if (i == j) continue;
      merged.edges.push_back({i, j});
      merged.edge_rest_mm.push_back(0.5 * (seg.la[k] + seg.lb[k]));
    }
  }

  // Phase B: relax the sewn garment under gravity until it settles (ARAP sewing only: the
  // XPBD-sewn garment goes to the drape as sewn, untangled).
  if (options.solver == SewSolver::kXpbd) {
    if (!two_level || options.xpbd_relax_s <= 0) return finish_garment(pattern, meshes, offset, mc, st, t0);
    // Two levels: the fine garment lies on the coarse one, whose flat triangles cut the body's
    // curves and whose seams are the coarse level's; a short settle on the fine level without
    // weight lets its own contact, strain and seam constraints finish it.
    Garment fine = finish_garment(pattern, meshes, offset, mc, st, t0);
    auto settled = internal::settle_fine_garment(fine, body, options, cancel);
    if (!settled) return fail(settled.error().with_context("pattern '" + pattern.name + "': settling the fine level"));
    st.relax_iterations = settled->substeps;
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return fine;
  }
  params.spring_weight = 0;
  params.edge_weight = options.seam_edge_weight;
  params.gravity_per_mm = options.gravity_per_mm;
  params.tolerance_mm = options.tolerance_mm;
  // Accelerated first; plain local-global at the end, which settles contact monotonically.
  params.iterations = options.relax_iterations * 3 / 5;
  auto r = internal::relax_cloth(merged, body, params, cancel);
  if (!r) return fail(r.error().with_context("pattern '" + pattern.name + "': relaxing"));
  st.relax_iterations = r->iterations;
  params.anderson_window = 0;
  params.iterations = options.relax_iterations - params.iterations;
  r = internal::relax_cloth(merged, body, params, cancel);
  if (!r) return fail(r.error().with_context("pattern '" + pattern.name + "': relaxing"));
  st.relax_iterations += r->iterations;
  st.last_move_mm = r->last_move_mm;
  st.contacts = r->contacts;
  return finish_garment(pattern, meshes, offset, mc, st, t0);
}

}  // namespace tp::geometry
