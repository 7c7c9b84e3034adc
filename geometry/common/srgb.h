// geometry/common/srgb.h: the sRGB transfer curve (IEC 61966-2-1), defined once for geometry and rip.
#pragma once

#include <cmath>

namespace tp {

/// sRGB-encoded value (0..1) to linear light.
[[nodiscard]] inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// Linear light to sRGB encoding, clamped to 0..1 (NaN encodes as 0).
[[nodiscard]] inline double linear_to_srgb(double c) {
  if (!(c > 0)) return 0;
  if (c >= 1) return 1;
  return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

/// The float form of linear_to_srgb, for per-pixel loops that work in float.
[[nodiscard]] inline float linear_to_srgb(float c) {
  if (!(c > 0.0f)) return 0.0f;
  if (c >= 1.0f) return 1.0f;
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace tp
