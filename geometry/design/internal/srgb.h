// geometry/design/internal/srgb.h: sRGB transfer curve tables for filtering in linear light.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace tp::geometry::internal {

/// sRGB-encoded value (0..1) to linear light (IEC 61966-2-1).
inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// Linear light (0..1) to sRGB encoding.
inline double linear_to_srgb(double c) {
  if (c <= 0) return 0;
  if (c >= 1) return 1;
  return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

/// The 256 linear values of the 8-bit sRGB codes.
inline const std::array<float, 256>& srgb8_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[static_cast<size_t>(i)] = static_cast<float>(srgb_to_linear(i / 255.0));
    return t;
  }();
  return table;
}

/// Linear light to the nearest 8-bit sRGB code.
inline std::uint8_t linear_to_srgb8(double c) {
  return static_cast<std::uint8_t>(std::lround(linear_to_srgb(c) * 255.0));
}

}  // namespace tp::geometry::internal
