// geometry/sewing/internal/arap_solver.h: local-global (projective dynamics) relaxation of a cloth
// mesh against its 2D rest shape, with seam springs, gravity and body contact.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/common/cancel.h"
#include "geometry/common/error.h"
#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// The cloth: 3D positions, triangles with their 2D rest shape, and zero-length seam springs.
struct ClothMesh {
  std::vector<Vec3> x_mm;                       ///< #V current positions, updated in place
  std::vector<std::array<int, 3>> triangles;    ///< #F indices into x_mm
  std::vector<std::array<Vec2, 3>> rest_mm;     ///< #F rest (pattern) positions of the corners
  std::vector<std::array<int, 2>> springs;      ///< vertex pairs drawn together (phase A seams)
  /// Edges held to a rest length (sewn seam segments: the stitching keeps the seam's length).
  std::vector<std::array<int, 2>> edges;
  std::vector<double> edge_rest_mm;             ///< #edges rest lengths
};

/// Weights and limits of one relaxation run. Weights are relative to the membrane stiffness.
struct ClothParams {
  double spring_weight = 0;        ///< seam spring stiffness (0: no springs)
  double edge_weight = 0;          ///< stiffness of the rest-length edges (0: edges ignored)
  double proximal_weight = 0.02;   ///< pull towards the previous iterate (damping), per vertex area / h^2
  double gravity_per_mm = 0;    ///< body force per unit area, relative to membrane stiffness (-y)
  double clearance_mm = 3;         ///< vertices are pushed at least this far out of the body
  int iterations = 100;
  double tolerance_mm = 0.005;     ///< stop when no vertex moves further in one iteration
  int threads = 2;
  int anderson_window = 5;         ///< Anderson acceleration history (0: plain local-global)
  std::function<void()> on_iteration;  ///< called once per iteration (progress), may be empty
};

/// Outcome of a run.
struct ClothStats {
  int iterations = 0;
  double last_move_mm = 0;
  int contacts = 0;  ///< vertices pushed out of the body in the last iteration
};

/// Minimises sum_t A_t |F_t - R_t|^2 + springs + edges + gravity by local-global iterations (the
/// system matrix is factorised once), projecting any vertex closer than clearance to the body
/// back out after every global step, so the result never ends inside the body.
/// Fails with kSewing if the system cannot be factorised, kCancelled when `cancel` fires.
[[nodiscard]] Result<ClothStats> relax_cloth(ClothMesh& cloth, const BodySdf& body, const ClothParams& params,
                                             const CancelToken* cancel);

/// Pushes every vertex closer than `clearance_mm` to the body out along the body normal; a
/// vertex deeper inside than the SDF's band goes back to `fallback` (if given). Returns how
/// many moved.
int push_out_of_body(std::vector<Vec3>& x_mm, const BodySdf& body, double clearance_mm, int threads,
                     const std::vector<Vec3>* fallback = nullptr);

}  // namespace tp::geometry::internal
