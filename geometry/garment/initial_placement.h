// geometry/garment/initial_placement.h: where each piece starts in 3D before it is sewn.
#pragma once

#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/garment/push_out_of_body.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// How far outside the body pieces start (mm): the sewing clearance (3), the self-collision
/// thickness (2) and a few mm to spare, so contact does not hold a seam before it closes.
inline constexpr double kStartClearance_mm = 10;
/// Radius (mm, in the flat piece) over which one vertex's push out of the body spreads.
inline constexpr double kPushRadius_mm = 120;

/// Start positions (mm, body frame) of every vertex of every piece mesh.
///
/// A piece with a Placement3d is placed by it, then rolled (isometrically) onto a cylinder
/// whose axis is parallel to the piece's placed y axis: a piece sewn to itself across its
/// width (sleeve, waistband) becomes a tube of its own width; a near-vertical piece facing
/// the body's vertical axis is rolled around that axis at its own distance. Pieces without a
/// placement are first given one from their role and the body's landmarks (role_placements:
/// fronts in front, backs behind, sleeves along the arms, waistbands at the waist). Last, every
/// piece is pushed out of the body to `clearance_mm` by a smooth field (push_out_of_body): no
/// piece starts inside the body, whatever placed it. `stats` (optional) gets the vertices
/// inside before and after that push.
std::vector<std::vector<Vec3>> initial_placement(const Pattern& pattern, const PatternMesh& meshes, const BodySdf& body,
                                                 double clearance_mm = kStartClearance_mm,
                                                 PushOutStats* stats = nullptr);

}  // namespace tp::geometry
