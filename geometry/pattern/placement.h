// geometry/pattern/placement.h: 3D placement of pieces around the body (rotations, application).
#pragma once

#include <array>

#include "geometry/common/vec.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Row-major rotation R = Rz * Ry * Rx from Euler angles in degrees (the x rotation is applied
/// first), the convention of GarmentCode and of the native format's rotation_deg.
std::array<double, 9> rotation_from_euler_xyz_deg(double rx_deg, double ry_deg, double rz_deg);

/// Euler angles in degrees (rx, ry, rz) of a rotation, inverse of rotation_from_euler_xyz_deg.
Vec3 euler_xyz_deg_from_rotation(const std::array<double, 9>& r);

/// The 3D point (mm, body frame) of piece point `p_mm`: rotation * (x, y, 0) + translation.
Vec3 place_point(const Placement3d& placement, Vec2 p_mm);

}  // namespace tp::geometry
