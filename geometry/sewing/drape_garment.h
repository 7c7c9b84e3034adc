// geometry/sewing/drape_garment.h: the sewn garment settled under gravity on the body with a fabric.
#pragma once

#include <functional>

#include "geometry/body/body_sdf.h"
#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/garment/garment.h"
#include "geometry/sewing/cloth_material.h"

namespace tp::geometry {

/// Controls of draping. Defaults are the ones docs/garments.md measures.
struct DrapeOptions {
  ClothMaterial material;            ///< default: cotton-poplin
  double duration_s = 1.0;           ///< simulated time limit (stops earlier once settled)
  /// Substep length: 1.25 ms with 8 strain passes keeps the hanging weight's strain within 5 %
  /// where 2.5 ms with 16 did not (cotton-poplin, 10,000 vertices, one run each, draped strain
  /// p95 and drape s: shirt_mean 0.0774 -> 0.0409 and 10.6 -> 11.9, hoody_mean 0.0670 -> 0.0367
  /// and 11.1 -> 12.6, FreeSewing teagan 34 0.0514 -> 0.0269 and 10.5 -> 10.0); more substeps
  /// carry a correction further than more passes in one (Macklin et al. 2019).
  double substep_s = 1.0 / 800;
  double damping_per_s = 4;
  double clearance_mm = 3;           ///< distance kept from the body (as sewing's)
  double self_thickness_mm = 2;      ///< distance kept between layers of the garment
  /// Stops once the vertices' RMS speed across each of `settle_windows` windows of
  /// `settle_window_s` in a row is below this (displacement over the window, not the jitter of
  /// one substep).
  double settle_speed_mm_s = 4;
  double settle_window_s = 0.05;
  int settle_windows = 2;
  /// Strain-limiting passes over every triangle per substep (Gauss-Seidel). Measured on
  /// simple_top at 4,000 vertices (cotton-poplin): draped strain p95 0.099 with 4 passes, 0.063
  /// with 8, 0.043 with 16 (the garment's weight hangs from the shoulders and each pass carries
  /// the correction one triangle further). 8 with 1.25 ms substeps (above).
  int stretch_passes = 8;
  int threads = 2;
  /// Progress: the share of `duration_s` simulated, called every few substeps (may be empty).
  std::function<void(double fraction)> on_progress;
};

/// What draping did.
struct DrapeStats {
  int substeps = 0;
  double simulated_s = 0;
  double max_speed_mm_s = 0;
  double settle_speed_mm_s = 0;  ///< RMS speed over the last settle window
  bool settled = false;          ///< stopped by the settle test (else at duration_s)
  int body_contacts = 0;
  int self_contacts = 0;
  double seconds = 0;  ///< wall time
};

/// Drapes `sewn` (a 3D garment from sew_garment) on `body`: XPBD steps with each triangle
/// strain-limited to its 2D shape, dihedral bending, self-collision (point-triangle and
/// edge-edge through a spatial hash, substeps short enough that nothing tunnels), body contact
/// with the material's friction, gravity and damping. The result has the same charts and
/// vertex numbering; only positions change. Same input, same output to the bit.
/// Fails with kInvalidArgument for a bad material, kSewing if the solver diverges,
/// kCancelled when `cancel` fires.
[[nodiscard]] Result<Garment> drape_garment(const Garment& sewn, const BodySdf& body, const DrapeOptions& options,
                                            DrapeStats* stats = nullptr, const CancelToken* cancel = nullptr);

}  // namespace tp::geometry
