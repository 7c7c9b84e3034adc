// geometry/sewing/internal/xpbd_solver.cpp: XPBD cloth stepping (Macklin et al. 2016 and 2019,
// "XPBD" and "Small steps in physics simulation"), constraints projected Gauss-Seidel in a fixed
// order so a run is bit-for-bit repeatable.
#include "geometry/sewing/internal/xpbd_solver.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "geometry/common/thread_pool.h"
#include "geometry/sewing/internal/self_collision.h"
#include "geometry/sewing/internal/strain_blocks.h"

namespace tp::geometry::internal {
namespace {

/// A deformation whose largest squared singular value is below this has collapsed to a point.
constexpr double kZeroStretch = 1e-20;

/// A triangle's second singular value below this share of its first is degenerate (collapsed).
constexpr double kRelativeSingular = 1e-9;
/// Sweeps of the plain seams' segments after each strain pass, each forward then back along them.
/// Draped plain seams' largest difference at 10,000 vertices: hoody_mean 1.4 % with one forward
/// sweep, 0.8 % with two both ways, 0.5 % with four (shirt_mean 8.5 %, 5.3 %, 5.2 %). Measured
/// again 2026-12-07 with four, eight and sixteen: hoody_mean 0.53, 0.45, 0.42 %, dress_pencil
/// 0.98, 0.63, 0.59 %, shirt_mean 6.2, 6.2, 6.7 %, penelope 34 9.2, 5.2 % (four, eight); more
/// sweeps stiffen the cloth beside the seams: js_mean_all's draped strain p95 0.059, 0.064, 0.068.
constexpr int kSeamSweeps = 8;
/// Rounds of the drape's seam finish (run_xpbd, after the last substep), each the plain seams'
/// kSeamSweeps sweeps each way, self-collision and body contact.
constexpr int kSeamFinishRounds = 32;
/// A strain-limit correction along an edge shorter than this (mm) has no direction.
constexpr double kZeroLength_mm = 1e-12;
/// A widest stitch gap within kNearDoneGaps done gaps is still closing, if slowly: it has
/// kNearDoneStallTimes the stall time (penelope 34's tight waistband stopped 1.03 mm open by
/// the 1 % rule while closing by 0.01 mm in 0.5 s).
constexpr double kNearDoneGaps = 2;
constexpr double kNearDoneStallTimes = 4;
/// The strain (and bending) projections run in rounds of 2^3 vertex-disjoint blocks (whatever the
/// thread count), the bands between one round's blocks split again in the next, then the rest in
/// one thread.
constexpr int kStrainBlockLevels = 3;
constexpr int kStrainBlockRounds = 3;
/// A drape substep runs about 28 short parallel loops (8 strain passes of 3 rounds, the bending's
/// 3 rounds, the body pass): the workers poll between them rather than sleep (shirt_mean's drape at 10,174
/// vertices with 16 passes, one run each: strain passes 6.8 s sleeping, 6.0 s polling for 300 us).
constexpr int kPoolSpin_us = 300;

// Runs fn(begin, end) over fixed chunks of [0, n) on the pool; fn must only touch its own range.
template <class Fn>
void parallel_ranges(int n, ThreadPool& pool, Fn&& fn) {
  constexpr int kChunk = 1024;
  if (pool.size() == 1 || n < 2 * kChunk) {
    fn(0, n);
    return;
  }
  pool.parallel_for((n + kChunk - 1) / kChunk, [&](int c, int) { fn(c * kChunk, std::min(n, (c + 1) * kChunk)); });
}

double wrap_angle(double a) {
  while (a > std::numbers::pi) a -= 2 * std::numbers::pi;
  while (a < -std::numbers::pi) a += 2 * std::numbers::pi;
  return a;
}

// Whether body contact queries the vertex at `x`: only where the grid's interpolated distance (a
// cheap estimate, BodySdf::approx_distance_mm) is within the thickness plus 0.4 of a grid cell.
bool may_touch(const BodySdf& body, const Vec3& x, double thickness_mm) {
  return body.approx_distance_mm(x) <= thickness_mm + 0.4 * body.spacing_mm();
}

// One XPBD bending projection (lambda starts at 0 every substep: one iteration per substep).
void project_bend(const BendStencil& s, const std::vector<double>& w, double dt2, std::vector<Vec3>& x) {
  std::array<Vec3, 4> g;
  const double angle = dihedral_angle(x, s, &g);
  const double c = wrap_angle(angle - s.rest_angle);
  const int id[4] = {s.a, s.b, s.c, s.d};
  double denom = s.compliance / dt2;
  for (int k = 0; k < 4; ++k) denom += w[id[k]] * dot(g[k], g[k]);
  if (denom <= 0) return;
  const double lambda = -c / denom;
  for (int k = 0; k < 4; ++k) x[id[k]] += g[k] * (w[id[k]] * lambda);
}

// Puts triangle `t`'s corners at its rest shape mapped by the gradient [g0 g1], placed at the
// corners' centre of mass (current and rest alike), so the triangle's momentum is kept and no
// corner overshoots its goal. The corners' inverse masses must be positive.
void place_rest_shape(const RestTriangle& t, const std::vector<double>& w, const Vec3& g0, const Vec3& g1,
                      std::vector<Vec3>& x) {
  const double m0 = 1 / w[t.v[0]], m1 = 1 / w[t.v[1]], m2 = 1 / w[t.v[2]], msum = m0 + m1 + m2;
  const Vec3 c = (x[t.v[0]] * m0 + x[t.v[1]] * m1 + x[t.v[2]] * m2) / msum;
  const Vec2 rc = (t.rest_mm[0] * m0 + t.rest_mm[1] * m1 + t.rest_mm[2] * m2) / msum;
  for (int k = 0; k < 3; ++k) {
    const Vec2 r = t.rest_mm[k] - rc;
    x[t.v[k]] = c + g0 * r.x + g1 * r.y;
  }
}

// Plain seams' segments back to their pattern length (hard distance constraints, in order).
// After the strain passes alone the seams came out 1-3 % longer than cut (shirt_mean's underarm
// seams 312 mm sewn 318-319 mm), since each pass leaves the last triangles it touched stretched
// by their neighbours. One sweep along a seam's chain of segments leaves each pulled by the next
// (hoody_mean's draped seams 1.4 % long); kSeamSweeps forward and back (figures at the constant).
void project_seam_edges(const ClothModel& cloth, std::vector<Vec3>& x) {
  auto project = [&](const SeamEdge& e) {
    const Vec3 d = x[e.a] - x[e.b];
    const double len = norm(d);
    const double wsum = cloth.inv_mass[e.a] + cloth.inv_mass[e.b];
    if (wsum <= 0 || len < kZeroLength_mm) return;
    const Vec3 corr = d * ((len - e.rest_mm) / (len * wsum));
    x[e.a] -= corr * cloth.inv_mass[e.a];
    x[e.b] += corr * cloth.inv_mass[e.b];
  };
  for (int sweep = 0; sweep < kSeamSweeps; ++sweep) {
    for (const SeamEdge& e : cloth.seam_edges) project(e);
    for (auto it = cloth.seam_edges.rbegin(); it != cloth.seam_edges.rend(); ++it) project(*it);
  }
}

// The zones each vertex is in now: its stitch sides whose pair is still further apart than the
// vertex is from the side (in the pattern).
void update_seam_zones(ClothModel& cloth) {
  const int n = static_cast<int>(cloth.x_mm.size());
  cloth.seam_zone_active.resize(n);
  for (int i = 0; i < n; ++i) {
    auto& active = cloth.seam_zone_active[i];
    active.clear();
    for (const ClothModel::SeamZone& z : cloth.seam_zones[i]) {
      const auto& pr = cloth.stitches[z.pair];
      if (z.distance_mm < norm(cloth.x_mm[pr[0]] - cloth.x_mm[pr[1]])) active.push_back(z.code);
    }
    std::sort(active.begin(), active.end());
  }
}

}  // namespace

void project_triangle(const RestTriangle& t, const std::vector<double>& w, double limit, double stiffness,
                      std::vector<Vec3>& x) {
  const Vec3 x0 = x[t.v[0]], x1 = x[t.v[1]], x2 = x[t.v[2]];
  const Vec3 d1 = x1 - x0, d2 = x2 - x0;
  // F = [d1 d2] Dm^-1, columns f0 and f1.
  const Vec3 f0 = d1 * t.dm_inv[0][0] + d2 * t.dm_inv[1][0];
  const Vec3 f1 = d1 * t.dm_inv[0][1] + d2 * t.dm_inv[1][1];
  const double a = dot(f0, f0), b = dot(f0, f1), d = dot(f1, f1);
  const double tr = a + d, det = a * d - b * b;
  if (stiffness >= 1 && t.min_stretch <= 0 && det > kRelativeSingular * kRelativeSingular * tr * tr) {
    // Full stiffness: every stretch's target is 1, so the target gradient is F's rotation,
    // F (F^T F)^(-1/2), with the 2x2 square root in closed form: sqrt(C) = (C + sqrt(det C) I) /
    // sqrt(tr C + 2 sqrt(det C)), whose determinant is sqrt(det C). The same goal as the general
    // path below with two square roots and one division instead of four and five (the strain
    // passes were 38 % of a garment's sewing and drape).
    if (w[t.v[0]] <= 0 || w[t.v[1]] <= 0 || w[t.v[2]] <= 0) return;
    const double root_det = std::sqrt(det);
    const double scale = 1 / (root_det * std::sqrt(tr + 2 * root_det));
    const Vec3 g0 = (f0 * (d + root_det) - f1 * b) * scale;
    const Vec3 g1 = (f1 * (a + root_det) - f0 * b) * scale;
    place_rest_shape(t, w, g0, g1, x);
    return;
  }
  // Singular values and right vectors from the eigen-decomposition of F^T F.
  const double disc = std::sqrt(std::max(tr * tr / 4 - det, 0.0));
  const double l1 = tr / 2 + disc, l2 = std::max(tr / 2 - disc, 0.0);
  if (l1 < kZeroStretch) return;
  // The right singular vector, normalised by sqrt (std::hypot, in normalized(Vec2), cost 6 % of a
  // garment's sewing and drape).
  Vec2 v1 = a >= d ? Vec2{1, 0} : Vec2{0, 1};
  if (std::abs(b) > 1e-30) {
    const Vec2 u{b, l1 - a};
    v1 = u / std::sqrt(u.x * u.x + u.y * u.y);
  }
  const Vec2 v2 = perp(v1);
  const double s1 = std::sqrt(l1), s2 = std::sqrt(l2);
  const Vec3 u1 = (f0 * v1.x + f1 * v1.y) / s1;
  Vec3 u2 = s2 > kRelativeSingular * s1 ? (f0 * v2.x + f1 * v2.y) / s2 : Vec3{};
  if (s2 <= kRelativeSingular * s1) {
    // A collapsed triangle: any direction orthogonal to the stretched one.
    const Vec3 o = std::abs(u1.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u2 = normalized(cross(cross(u1, o), u1));
  }
  // Target stretches: inside the limit, pulled towards rest by the stiffness.
  auto target = [&](double sv) {
    // Gathered: the seam's pleats take the compression.
    if (sv < 1 && t.min_stretch > 0) return std::max(sv, t.min_stretch);
    const double clamped = std::clamp(sv, 1 - limit, 1 + limit);
    return clamped + stiffness * (1 - clamped);
  };
  const double t1 = target(s1), t2 = target(s2);
  if (t1 == s1 && t2 == s2) return;
  // Target gradient U diag(t) V^T applied to the rest corners around the current centroid.
  const Vec3 g0 = u1 * (t1 * v1.x) + u2 * (t2 * v2.x);
  const Vec3 g1 = u1 * (t1 * v1.y) + u2 * (t2 * v2.y);
  if (w[t.v[0]] <= 0 || w[t.v[1]] <= 0 || w[t.v[2]] <= 0) return;
  place_rest_shape(t, w, g0, g1, x);
}

Result<XpbdStats> run_xpbd(ClothModel& cloth, const BodySdf& body, const XpbdParams& p, const CancelToken* cancel) {
  XpbdStats st;
  std::vector<Vec3>& x = cloth.x_mm;
  const int n = static_cast<int>(x.size());
  if (n == 0) return st;
  const double dt = p.substep_s, dt2 = dt * dt;
  const double decay = std::exp(-p.damping_per_s * dt);
  const int total = static_cast<int>(std::ceil(p.duration_s / dt));
  const double pad_mm = std::max(p.broad_phase_pad_mm, 0.05);
  ThreadPool pool(std::clamp(p.threads, 1, 8), kPoolSpin_us);
  // Per-substep travel budget: inertial motion is clamped to it and any move (constraints
  // included) to twice it. It follows the cloth's speed (1.5 x the fastest vertex's last
  // substep), at most max_move. The pairs are searched again before any vertex can have moved
  // more than the pad from where the last search saw it, so pairs farther apart than the
  // thickness plus twice the pad then cannot touch before the next search.
  double budget = p.max_move_mm;
  double last_move = p.max_move_mm;
  std::vector<Vec3> v(n, Vec3{}), prev(n), x_searched;
  double moved_mm = 1e300;  // the farthest any vertex is from where the last search saw it
  std::vector<uint8_t> touching(n, 0);
  std::vector<Vec3> normal(n);
  std::vector<double> depth(n);
  SelfCollisionPairs pairs;
  SelfCollisionScratch scratch;
  StrainBlocks blocks = plan_strain_blocks(cloth.triangles, cloth.inv_mass, x, kStrainBlockLevels, kStrainBlockRounds);
  const ElementRounds bend_blocks = plan_bend_blocks(cloth.bends, x, kStrainBlockLevels, kStrainBlockRounds);
  // Sewing: every stitched pair's allowed distance shrinks from its start at a fixed speed.
  const bool sewing = !cloth.stitches.empty();
  std::vector<double> stitch_start(cloth.stitches.size());
  double widest = 0;
  for (size_t k = 0; k < cloth.stitches.size(); ++k) {
    stitch_start[k] = norm(x[cloth.stitches[k][0]] - x[cloth.stitches[k][1]]);
    widest = std::max(widest, stitch_start[k]);
  }
  const double close_s = p.stitch_close_mm_s > 0 ? widest / p.stitch_close_mm_s : 0;
  double best_gap = 1e300, best_at_s = 0;
  // Draping's settle test: displacement across windows of settle_window_s.
  const int window_steps = std::max(1, static_cast<int>(std::lround(p.settle_window_s / dt)));
  std::vector<Vec3> x_window = x;
  int window_start = 0, calm_windows = 0;

  for (int step = 0; step < total; ++step) {
    if (cancel && cancel->cancelled()) return fail(ErrorCode::kCancelled, "draping cancelled");
    budget = std::clamp(1.5 * last_move + 0.05, 0.05, p.max_move_mm);
    if (moved_mm + 2 * budget > pad_mm) {
      if (p.on_progress) p.on_progress(static_cast<double>(step) / total);
      if (!cloth.seam_zones.empty()) update_seam_zones(cloth);
      pairs = find_self_collision_pairs(cloth, x, p.self_thickness_mm + 2 * pad_mm, &pool, &scratch);
      st.self_pairs = static_cast<int>(pairs.point_triangle.size() + pairs.edge_edge.size());
      x_searched = x;
      moved_mm = 0;
    }
    // Predict: gravity and damping on the velocities, positions advanced.
    prev = x;
    for (int i = 0; i < n; ++i) {
      if (cloth.inv_mass[i] == 0) continue;
      v[i].y -= p.gravity_mm_s2 * dt;
      v[i] = v[i] * decay;
      const double speed = norm(v[i]);
      if (speed * dt > budget) v[i] = v[i] * (budget / (speed * dt));
      x[i] += v[i] * dt;
    }
    // Membrane (each pass followed by the stitches, so seams are not left to the last word of
    // the strain limit), then bending, in their fixed order. Each membrane pass runs its blocks
    // in parallel: they share no vertex, so the result is one whatever runs them.
    const double closed_mm = p.stitch_close_mm_s > 0 ? p.stitch_close_mm_s * (step + 1) * dt : 1e300;
    auto project_stitches = [&] {
      for (size_t k = 0; k < cloth.stitches.size(); ++k) {
        const int i = cloth.stitches[k][0], j = cloth.stitches[k][1];
        const double allowed = std::max(stitch_start[k] - closed_mm, 0.0);
        const Vec3 d = x[i] - x[j];
        const double len = norm(d);
        const double wsum = cloth.inv_mass[i] + cloth.inv_mass[j];
        if (len <= allowed || wsum <= 0 || len < kZeroLength_mm) continue;
        const Vec3 corr = d * ((len - allowed) / (len * wsum));
        x[i] -= corr * cloth.inv_mass[i];
        x[j] += corr * cloth.inv_mass[j];
      }
    };
    for (int pass = 0; pass < p.stretch_passes; ++pass) {
      project_strain_blocks(blocks, cloth.triangles, cloth.inv_mass, p.stretch_limit, p.stretch_stiffness, pool, x);
      if (sewing) project_stitches();
      project_seam_edges(cloth, x);
    }
    // Bending in blocks of stencils that share no vertex, as the strain passes (shirt_mean's drape
    // at 10,174 vertices: 2.0 s in one thread, 1.45 s so; 15 % of the stencils are left serial).
    for (const auto& round : bend_blocks.rounds)
      pool.parallel_for(static_cast<int>(round.size()), [&](int b, int) {
        for (int k : round[b]) project_bend(cloth.bends[k], cloth.inv_mass, dt2, x);
      });
    for (int k : bend_blocks.serial) project_bend(cloth.bends[k], cloth.inv_mass, dt2, x);
    // The stitches again after bending: bending near a seam line otherwise reopens it (a
    // 1.7-2.2 mm gap held on dress_pencil).
    if (sewing) project_stitches();
    project_seam_edges(cloth, x);
    // No vertex travels further than twice the budget in a substep: pairs cannot tunnel.
    for (int i = 0; i < n; ++i) {
      const Vec3 d = x[i] - prev[i];
      const double len = norm(d);
      if (len > 2 * budget) x[i] = prev[i] + d * (2 * budget / len);
    }
    st.self_contacts = resolve_self_collisions(cloth, pairs, p.self_thickness_mm, x);
    // Body contact with Coulomb friction (Macklin et al. 2014): the tangential motion of a
    // touching vertex is cancelled up to friction x penetration.
    parallel_ranges(n, pool, [&](int b, int e) {
      for (int i = b; i < e; ++i) {
        touching[i] = 0;
        if (!may_touch(body, x[i], p.body_thickness_mm)) continue;
        const BodySdf::Hit h = body.query(x[i]);
        if (!h.near || h.distance_mm >= p.body_thickness_mm) {
          // Deeper than the band: the constraints (a stitch partner, neighbours outside) may
          // draw the vertex out, but no move may take it deeper (the grid's distance must not
          // fall). Undoing every move held such a vertex where it started for good (the
          // blouse's left side seam at the hem, 30 mm open at 4,000 vertices).
          if (!h.near && h.distance_mm < 0 && body.approx_distance_mm(x[i]) < body.approx_distance_mm(prev[i]))
            x[i] = prev[i];
          continue;
        }
        touching[i] = 1;
        depth[i] = p.body_thickness_mm - h.distance_mm;
        normal[i] = h.normal;
        x[i] = h.closest_mm + h.normal * p.body_thickness_mm;
      }
    });
    int contacts = 0;
    for (int i = 0; i < n; ++i) {
      if (!touching[i]) continue;
      ++contacts;
      const Vec3 moved = x[i] - prev[i];
      const Vec3 tangential = moved - normal[i] * dot(moved, normal[i]);
      const double tl = norm(tangential);
      const double hold = p.friction * depth[i];
      x[i] -= tl <= hold ? tangential : tangential * (hold / tl);
    }
    st.body_contacts = contacts;
    // The plain seams the last word (draping): contact with friction holds a touching vertex
    // where the step began, so a seam stretched over the body stayed so (the blouse's 17.03 mm
    // shoulder seams draped at 17.49 mm, 2.7 %).
    if (p.seams_after_contact) project_seam_edges(cloth, x);
    double moved2 = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3 d = x[i] - x_searched[i];
      moved2 = std::max(moved2, dot(d, d));
    }
    moved_mm = std::sqrt(moved2);
    // Velocities from the positions.
    double vmax = 0;
    for (int i = 0; i < n; ++i) {
      v[i] = (x[i] - prev[i]) / dt;
      const double v2 = dot(v[i], v[i]);
      vmax = std::max(vmax, v2);
    }
    st.max_speed_mm_s = std::sqrt(vmax);
    last_move = st.max_speed_mm_s * dt;
    st.substeps = step + 1;
    st.simulated_s = st.substeps * dt;
    if (!std::isfinite(st.max_speed_mm_s)) return fail(ErrorCode::kSewing, "cloth drape diverged");
    if (sewing) {
      // Sewn: the seams closed (checked once the widest has had the time to close).
      if (st.simulated_s < close_s) continue;
      double gap = 0;
      for (const auto& pr : cloth.stitches) gap = std::max(gap, norm(x[pr[0]] - x[pr[1]]));
      st.stitch_gap_max_mm = gap;
      if (gap < p.stitch_done_mm) break;
      // Stalled: the widest gap has not narrowed by 1 % for the stall time (a seam held open).
      if (gap < 0.99 * best_gap) best_gap = gap, best_at_s = st.simulated_s;
      const double stall_s =
          gap < kNearDoneGaps * p.stitch_done_mm ? kNearDoneStallTimes * p.stitch_stall_s : p.stitch_stall_s;
      if (st.simulated_s - best_at_s > stall_s) break;
      continue;
    }
    // Settled: the RMS speed over each of the last windows below the settle speed. The
    // instantaneous speeds never settle: contact and the strain limit keep a few vertices
    // moving by a travel budget per substep back and forth (115-120 mm/s), and the test that
    // all but 0.5 % be slower than 4 mm/s never stopped a garment's drape.
    if (step + 1 - window_start >= window_steps) {
      double sum2 = 0;
      for (int i = 0; i < n; ++i) {
        const Vec3 d = x[i] - x_window[i];
        sum2 += dot(d, d);
      }
      st.settle_speed_mm_s = std::sqrt(sum2 / n) / ((step + 1 - window_start) * dt);
      calm_windows = st.settle_speed_mm_s < p.settle_speed_mm_s ? calm_windows + 1 : 0;
      x_window = x;
      window_start = step + 1;
      if (calm_windows >= std::max(p.settle_windows, 1)) {
        st.settled = true;
        break;
      }
    }
  }
  // The drape's seam finish. In each substep the membrane and contact stretch a long plain seam
  // again after its sweeps: dress_pencil's centre back settled 0.53 % long (516.48 mm cut, 519.20
  // mm draped). Rounds of the seams' sweeps, self-collision on a fresh search and body contact
  // without friction, last, so no vertex ends inside the clearance, bring such a seam to its
  // length (516.50 mm); a seam the body holds open (a waistband smaller round than the body under
  // it at the clearance) keeps the length the body gives it. The cloth beside a seam does not
  // follow its vertices: draped strain p95 rises (simple_top 3.9 % to 4.9 %; docs/garments.md).
  // Tried (2026-12-07, the corpus at 10,000 vertices): the sweeps alone pulled penelope's
  // waistbands and skirt8's band into the body (42-52 vertices inside); without self-collision
  // the 2021 tee crossed itself (42 pairs); a strain pass in each round stretched the seam again
  // (dress_pencil's centre back 520.35 mm), or, with the sweeps four times over, left the tee
  // crossing itself (15 pairs) and shirt_mean's seams 0.56 % long.
  if (p.seams_after_contact && !cloth.seam_edges.empty()) {
    pairs = find_self_collision_pairs(cloth, x, p.self_thickness_mm + 2 * pad_mm, &pool, &scratch);
    for (int round = 0; round < kSeamFinishRounds; ++round) {
      project_seam_edges(cloth, x);
      resolve_self_collisions(cloth, pairs, p.self_thickness_mm, x);
      parallel_ranges(n, pool, [&](int b, int e) {
        for (int i = b; i < e; ++i) {
          if (!may_touch(body, x[i], p.body_thickness_mm)) continue;
          const BodySdf::Hit h = body.query(x[i]);
          if (h.near && h.distance_mm < p.body_thickness_mm) x[i] = h.closest_mm + h.normal * p.body_thickness_mm;
        }
      });
    }
  }
  return st;
}

}  // namespace tp::geometry::internal
