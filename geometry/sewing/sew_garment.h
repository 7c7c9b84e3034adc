// geometry/sewing/sew_garment.h: the 3D garment: pieces meshed, placed, sewn and relaxed on a body.
#pragma once

#include <functional>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/garment/garment.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// How the seams are closed: ARAP springs (no self-collision), or the XPBD cloth solver with
/// self-collision from the first step (the drape's solver), whose layers cannot pass through
/// each other.
enum class SewSolver { kArap, kXpbd };

/// Controls of sewing and relaxation.
struct SewOptions {
  SewSolver solver = SewSolver::kArap;
  double target_edge_mm = 20;        ///< meshing size bound (see mesh_pattern)
  /// Sew first on a mesh this many times coarser, then refine (0 or < 1.5: single level; < 0: the
  /// solver's default). XPBD sewing: 2 by default, less where the coarse edge would exceed
  /// kMaxCoarseEdge_mm, one level below 1.5 (its self-collision keeps the coarse garment
  /// untangled; the fine garment is its interpolation, settled for xpbd_relax_s on its own); a
  /// default coarse level that leaves a seam open or passes through itself is sewn again a little
  /// finer, then discarded for one level (SewStats::coarse_discarded, coarse_fallback_*). ARAP: off by
  /// default: on GarmentCode's shirt_mean the coarse mesh tangled a sleeve (strain 3.1 % mean,
  /// 10.3 % p95 at 10,000 vertices, against 1.2 % and 4.1 % sewn in one level).
  double coarse_factor = -1;
  double clearance_mm = 3;           ///< garment vertices end at least this far outside the body
  int sewing_iterations = 480;       ///< phase A: seams drawn together by stiffening springs
  int relax_iterations = 400;        ///< phase B: seams merged, relaxed under gravity
  /// Weight per area relative to membrane stiffness. Contact is frictionless, so any weight
  /// slides a garment down the body until it is stretched over it: 0 keeps the placement's height.
  double gravity_per_mm = 0;
  double tolerance_mm = 0.003;       ///< phase B stops when no vertex moves further per iteration
  /// Phase B: stiffness of the sewn seams' segments against their pattern length, relative to
  /// the membrane (0: seams stretch like the fabric around them).
  double seam_edge_weight = 200;
  /// XPBD sewing: the speed at which each seam's allowed gap shrinks, the gap below which a
  /// seam counts as closed (its sides are then merged), the simulated time limit, and the
  /// distance kept between layers. No ARAP relaxation follows (the drape settles the garment).
  double xpbd_close_mm_s = 250;
  double xpbd_done_gap_mm = 1;
  double xpbd_duration_s = 8;
  /// Also stops once the widest gap has not narrowed by 1 % for this long (four times as long
  /// once it is within twice xpbd_done_gap_mm).
  double xpbd_stall_s = 0.5;
  double xpbd_self_thickness_mm = 2;
  /// XPBD on two levels: the fine garment carried over from the coarse one is then settled on its
  /// own for at most this long (simulated s; no weight, no friction; it stops earlier once still).
  /// 0: the fine garment as carried over.
  double xpbd_relax_s = 0.1;
  int threads = 2;
  /// Progress: the share of the planned sewing and relaxing iterations done, called once per
  /// iteration (may be empty). Phase B may stop early, so the last call can be below 1.
  std::function<void(double fraction)> on_progress;
};

/// The coarsest mesh edge (mm) a default coarse level is sewn at (see SewOptions::coarse_factor).
inline constexpr double kMaxCoarseEdge_mm = 32;
/// A default coarse level whose widest stitch gap ends above this many done gaps (or that passes
/// through itself) is discarded: sewn once more on a mesh kCoarseRetryFactor as coarse (not below
/// 1.5 x the fine edge), then on one level (SewStats::coarse_discarded, coarse_fallback_*).
inline constexpr double kCoarseFallbackGap = 2;
inline constexpr double kCoarseRetryFactor = 0.9;

/// What sewing did, for reports and benchmarks.
struct SewStats {
  int sewing_iterations = 0;
  int relax_iterations = 0;
  double last_move_mm = 0;
  int contacts = 0;       ///< vertices in contact with the body at the end
  int collapsed_triangles = 0;  ///< triangles whose corners sewing merged (left out of the solve)
  /// Per stitch, per sewn vertex pair: the distance (mm) between its two sides at the end of
  /// sewing, before they are merged (with coarse_factor: the coarse level's).
  std::vector<std::vector<double>> stitch_gap_mm;
  double seconds = 0;
  int levels = 1;  ///< 2 when the garment was first sewn on a coarser mesh (coarse_factor)
  /// The default coarse level left a seam open (its widest gap, mm, above kCoarseFallbackGap done
  /// gaps) or passed through itself (its intersecting triangle pairs), so the garment was sewn
  /// again on one level (the coarse level's time included in `seconds`); 0 and 0 otherwise.
  double coarse_fallback_gap_mm = 0;
  int coarse_fallback_self_intersections = 0;
  /// Default coarse levels discarded (open or crossing itself) before the one kept or the
  /// fallback to one level: 0, 1 or 2.
  int coarse_discarded = 0;
  double coarse_edge_mm = 0;  ///< two levels: the edge of the last coarse level sewn
};

/// Builds the 3D garment of `pattern` on `body`: meshes every piece (seam-matched), places
/// the pieces around the body (initial_placement), draws stitched vertex pairs together with
/// springs while the pieces keep their 2D shape (ARAP local-global, body contact with
/// `clearance_mm`), then merges each stitched pair into one 3D vertex and relaxes the garment
/// under gravity. With coarse_factor, all of this first runs on a coarser mesh of the same
/// pattern, whose result is interpolated (through the 2D charts) onto the fine mesh, which is
/// then only relaxed: low-frequency motion converges on the coarse mesh. Vertex positions are in the body frame (mm). The pieces of the result keep
/// their 2D meshes as texture coordinates. Fails with the meshing error, kSewing when the
/// solver fails, kCancelled when `cancel` fires.
[[nodiscard]] Result<Garment> sew_garment(const Pattern& pattern, const BodySdf& body, const SewOptions& options,
                                          SewStats* stats = nullptr, const CancelToken* cancel = nullptr);

/// The same from an existing seam-matched mesh of the pattern (mesh_pattern).
[[nodiscard]] Result<Garment> sew_garment(const Pattern& pattern, const PatternMesh& meshes, const BodySdf& body,
                                          const SewOptions& options, SewStats* stats = nullptr,
                                          const CancelToken* cancel = nullptr);

}  // namespace tp::geometry
