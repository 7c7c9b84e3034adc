// geometry/sewing/internal/xpbd_solver.h: the XPBD cloth time stepper (small steps, one
// constraint pass per substep): strain-limited stretch and shear per triangle, dihedral bending,
// self-collision, body contact with friction, gravity and damping.
#pragma once

#include <functional>

#include "geometry/body/body_sdf.h"
#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/sewing/internal/cloth_model.h"

namespace tp::geometry::internal {

/// Settings of one run. Length mm, time s.
struct XpbdParams {
  double duration_s = 1.0;           ///< simulated time limit
  double substep_s = 1.0 / 400;      ///< substep length
  /// Self-collision pairs are searched again before any vertex has moved this far from where the
  /// last search saw it; pairs closer than the thickness plus twice this are kept.
  double broad_phase_pad_mm = 3;
  double gravity_mm_s2 = 9810;       ///< along -y
  double damping_per_s = 4;          ///< velocity decays as exp(-damping t)
  double body_thickness_mm = 3;      ///< vertices stay this far out of the body
  double self_thickness_mm = 2;      ///< cloth layers stay this far apart
  /// No vertex moves further in one substep (below the self thickness, so nothing tunnels).
  double max_move_mm = 0.5;
  int stretch_passes = 4;            ///< stretch/shear projections per substep (Gauss-Seidel passes)
  double stretch_limit = 0.03;
  double stretch_stiffness = 1.0;
  double friction = 0.4;
  /// The plain seams' segments projected again after body contact, the last constraint of each
  /// substep, and after the last substep the seam finish (run_xpbd) brings them to their length
  /// (the drape; sewing and the fine level's settle leave contact the last word).
  bool seams_after_contact = false;
  /// Draping stops early once settled: the vertices' RMS speed over each window of
  /// `settle_window_s` (their displacement across it, so jitter in place does not count) stays
  /// below `settle_speed_mm_s` for `settle_windows` windows in a row.
  double settle_speed_mm_s = 4;
  double settle_window_s = 0.05;
  int settle_windows = 2;
  /// Sewing (cloth.stitches not empty): each stitched pair may be no further apart than its
  /// distance at the start minus this speed x time, so the seams close gradually (0: at once).
  double stitch_close_mm_s = 100;
  /// Sewing stops once every stitched pair is closer than this (and the cloth has had the time
  /// to close its widest gap); the settle test is not used.
  double stitch_done_mm = 1;
  /// Sewing also stops once the widest gap has not narrowed by 1 % for this long (simulated s;
  /// four times as long once the gap is within twice stitch_done_mm).
  double stitch_stall_s = 0.5;
  int threads = 2;  ///< strain passes, body queries and pair search; results do not depend on it
  /// Called at each broad phase with the share of the time limit simulated (progress), may be empty.
  std::function<void(double fraction)> on_progress;
};

/// What a run did.
struct XpbdStats {
  int substeps = 0;
  double simulated_s = 0;
  double max_speed_mm_s = 0;    ///< at the end
  double settle_speed_mm_s = 0;  ///< draping: the RMS speed over the last settle window
  bool settled = false;          ///< draping: stopped by the settle test, not the time limit
  int body_contacts = 0;        ///< vertices touching the body in the last substep
  int self_contacts = 0;        ///< pairs held apart in the last substep
  int self_pairs = 0;           ///< candidate pairs of the last broad phase
  double stitch_gap_max_mm = 0;  ///< sewing: the widest stitched pair at the end
};

/// Steps `cloth` (positions updated in place, starting at rest) under `p` on `body`.
/// Deterministic: constraints run in a fixed order; the strain passes in vertex-disjoint blocks
/// (strain_blocks.h) that are the same for any thread count; body queries are per vertex.
/// Fails with kSewing if positions stop being finite, kCancelled when `cancel` fires.
[[nodiscard]] Result<XpbdStats> run_xpbd(ClothModel& cloth, const BodySdf& body, const XpbdParams& p,
                                         const CancelToken* cancel);

/// One stretch/shear projection of triangle `t` (public for tests): the deformation gradient's
/// principal stretches are clamped to [1 - limit, 1 + limit] and pulled towards 1 by `stiffness`.
void project_triangle(const RestTriangle& t, const std::vector<double>& inv_mass, double limit, double stiffness,
                      std::vector<Vec3>& x);

}  // namespace tp::geometry::internal
