// geometry/pattern/placement.cpp: Euler rotations and placing piece points in 3D.
#include "geometry/pattern/placement.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tp::geometry {
namespace {

/// |sin(ry)| this close to 1 is gimbal lock: rx and rz are then not separable.
constexpr double kGimbalLockSlack = 1e-12;
constexpr double kDegToRad = std::numbers::pi / 180.0;
}

std::array<double, 9> rotation_from_euler_xyz_deg(double rx_deg, double ry_deg, double rz_deg) {
  double cx = std::cos(rx_deg * kDegToRad), sx = std::sin(rx_deg * kDegToRad);
  double cy = std::cos(ry_deg * kDegToRad), sy = std::sin(ry_deg * kDegToRad);
  double cz = std::cos(rz_deg * kDegToRad), sz = std::sin(rz_deg * kDegToRad);
  // Rz * Ry * Rx written out.
  return {cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx,
          sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx,
          -sy,     cy * sx,                cy * cx};
}

Vec3 euler_xyz_deg_from_rotation(const std::array<double, 9>& r) {
  double sy = std::clamp(-r[6], -1.0, 1.0);
  double ry = std::asin(sy);
  double rx, rz;
  if (std::abs(sy) < 1 - kGimbalLockSlack) {
    rx = std::atan2(r[7], r[8]);
    rz = std::atan2(r[3], r[0]);
  } else {
    // Gimbal lock: only rx - rz (or rx + rz) is defined; put it all in rx.
    rz = 0;
    rx = std::atan2(-r[5], r[4]);
  }
  return {rx / kDegToRad, ry / kDegToRad, rz / kDegToRad};
}

Vec3 place_point(const Placement3d& placement, Vec2 p_mm) {
  const auto& r = placement.rotation;
  return Vec3{r[0] * p_mm.x + r[1] * p_mm.y, r[3] * p_mm.x + r[4] * p_mm.y, r[6] * p_mm.x + r[7] * p_mm.y} +
         placement.translation_mm;
}

}  // namespace tp::geometry
