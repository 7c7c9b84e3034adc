// geometry/sewing/internal/xpbd_sewing.h: sewing with the XPBD cloth solver: the placed pieces'
// stitched vertex pairs drawn together gradually while self-collision keeps layers apart.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/sewing/cloth_material.h"
#include "geometry/sewing/sew_garment.h"

namespace tp::geometry::internal {

/// The longer side of an eased or gathered stitch: its stitched vertices in seam order (global
/// numbering) and the ratio of the shorter side's length to its own (< 1).
struct GatheredSide {
  int piece = 0;
  std::vector<int> vertices;
  double ratio = 1;
};

/// Settings of an XPBD sewing run (lengths mm, time s).
struct XpbdSewParams {
  ClothMaterial material;        ///< the fabric the pieces are simulated in while sewn
  double close_mm_s = 100;       ///< speed at which every seam's allowed gap shrinks
  double done_gap_mm = 1;        ///< sewn once every stitched pair is closer than this
  double duration_s = 8;         ///< simulated time limit
  double stall_s = 0.5;          ///< stop once the widest gap has not narrowed by 1 % for this long (x 4 near done)
  double clearance_mm = 3;       ///< distance kept from the body
  double self_thickness_mm = 2;  ///< distance kept between layers
  double damping_per_s = 10;
  int threads = 2;
  /// Eased and gathered stitches' longer sides: their triangles at the seam may compress to the
  /// ratio (the pleats of the seam line), so the longer side is gathered onto the shorter and the
  /// cloth beyond those triangles, which may not compress, buckles into folds.
  std::vector<GatheredSide> gathered;
  std::function<void(double fraction)> on_progress;
};

/// What the run did.
struct XpbdSewStats {
  int substeps = 0;
  double simulated_s = 0;
  double stitch_gap_max_mm = 0;
};

/// Sews the pieces of `meshes` (vertex v of piece p is x_mm[offset[p] + v], the placed start
/// positions, updated in place) with the stitched pairs `stitches` (global numbering): gravity
/// off, the pairs' allowed distance shrinking at `close_mm_s`, self-collision and body contact
/// active from the first substep. `pair_stitch` gives each pair's stitch: the cloth near the two
/// sides of one stitch, closer to them (in the pattern) than the pair is still open, does not
/// collide with each other, so sides that start overlapping can pass each other. Stops when every pair is within
/// `done_gap_mm` or at the time limit (the caller measures the gaps). Fails with kSewing if the solver diverges,
/// kCancelled.
[[nodiscard]] Result<XpbdSewStats> sew_pieces_xpbd(const PatternMesh& meshes, const std::vector<int>& offset,
                                                   const std::vector<std::array<int, 2>>& stitches,
                                                   const std::vector<int>& pair_stitch, const BodySdf& body,
                                                   const XpbdSewParams& p, std::vector<Vec3>& x_mm,
                                                   const CancelToken* cancel);

/// Settles a sewn garment (merged seams) on `body` without weight or friction for at most
/// `o.xpbd_relax_s` (XPBD in the sewing's steps: strain, seam segments, bending, self-collision,
/// body contact at `o.clearance_mm`), stopping once its RMS speed stays below the drape's settle
/// speed. Positions change in place. Fails with kSewing if the solver diverges, kCancelled.
[[nodiscard]] Result<XpbdSewStats> settle_fine_garment(Garment& g, const BodySdf& body, const SewOptions& o,
                                                       const CancelToken* cancel);

}  // namespace tp::geometry::internal
