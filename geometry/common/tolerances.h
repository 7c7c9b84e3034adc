// geometry/common/tolerances.h: the geometry layer's named tolerances, one per purpose, in place of bare 1e-9s.
#pragma once

namespace tp::geometry {

/// Two points closer than this (mm) are the same point: a polyline does not repeat it.
inline constexpr double kSamePoint_mm = 1e-9;

/// Two directions are parallel (no intersection is computed) when the determinant of the
/// 2x2 system is below this, relative to the product of the lengths involved where given.
inline constexpr double kParallelDeterminant = 1e-12;

/// Taken off a ratio before std::ceil, so a ratio that is whole up to rounding (10.000000001)
/// does not count one more segment, tap or step.
inline constexpr double kCeilSlack = 1e-9;

/// Smallest length (mm) or scale a division is made by, so a degenerate size never divides by zero.
inline constexpr double kMinDivisor = 1e-9;

/// Slack (mm or parameter units) of an inside/on-the-segment test, so a point exactly on a
/// boundary is on it despite rounding.
inline constexpr double kBoundarySlack = 1e-9;

}  // namespace tp::geometry
