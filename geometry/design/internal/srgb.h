// geometry/design/internal/srgb.h: 8-bit sRGB tables (over base/srgb.h's curve) for filtering in linear light.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "geometry/common/srgb.h"

namespace tp::geometry::internal {

using tp::linear_to_srgb;
using tp::srgb_to_linear;

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
