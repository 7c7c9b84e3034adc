// geometry/garment/initial_placement.h: where each piece starts in 3D before it is sewn.
#pragma once

#include <vector>

#include "geometry/body/body_sdf.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Start positions (mm, body frame) of every vertex of every piece mesh.
///
/// A piece with a Placement3d is placed by it, then rolled (isometrically) onto a cylinder
/// whose axis is parallel to the piece's placed y axis: a piece sewn to itself across its
/// width (sleeve, waistband) becomes a tube of its own width; a near-vertical piece facing
/// the body's vertical axis is rolled around that axis at its own distance. Pieces without a
/// placement are first given one from their role and the body's landmarks (role_placements:
/// fronts in front, backs behind, sleeves along the arms, waistbands at the waist).
std::vector<std::vector<Vec3>> initial_placement(const Pattern& pattern, const PatternMesh& meshes, const BodySdf& body);

}  // namespace tp::geometry
