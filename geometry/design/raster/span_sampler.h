// geometry/design/raster/span_sampler.h: filtered sampling of a mip image along a pixel span
// whose texture coordinates change linearly (one triangle, one row): the renderer's hot loop.
#pragma once

#include <cstdint>

#include "geometry/design/raster/mip_image.h"

namespace tp::geometry::internal {

/// How one triangle samples its image for one render call; chosen from the pixel footprint
/// (the Jacobian of texel coordinates per pixel), which is constant inside the triangle.
struct SpanFilter {
  enum class Kind : std::uint8_t { kBilinear, kTrilinear, kAnisotropic };
  Kind kind = Kind::kBilinear;
  int level = 0;            ///< finer level used (kBilinear: the only one)
  std::uint32_t fine_weight = 256;  ///< trilinear weight of `level` vs level + 1, 0..256
  int taps = 1;             ///< anisotropic: samples along the major axis
  double tap_du = 0, tap_dv = 0;  ///< level-0 texels between anisotropic taps
};

/// Picks the filter for a footprint. du_dx..dv_dy: level-0 texels per pixel step in x and y.
/// Magnified or 1:1 footprints sample level 0 bilinearly; minified ones use trilinear
/// filtering, with up to `max_taps` trilinear taps along the major axis when anisotropic.
SpanFilter choose_filter(const MipImage& image, double du_dx, double dv_dx, double du_dy, double dv_dy,
                         int max_taps = 8);

/// Writes `n` premultiplied texels for pixel centres u0 + k*du, v0 + k*dv (level-0 texel
/// units, texel centres at half-integers).
void sample_span(const MipImage& image, const SpanFilter& filter, double u0, double v0, double du,
                 double dv, int n, std::uint32_t* out);

/// The part [k0, k1) of such a span (0 <= k0 <= k1 <= n) outside which every sample is
/// transparent because it falls beyond the edge of an image that does not repeat: a motif
/// placed on part of a piece costs nothing where it is not. Conservative: [k0, k1) may include a
/// few transparent samples. The whole span when both axes repeat.
void covered_range(const MipImage& image, const SpanFilter& filter, double u0, double v0, double du, double dv,
                   int n, int& k0, int& k1);

/// One filtered sample (for tests and slow paths); same maths as sample_span.
std::uint32_t sample_point(const MipImage& image, const SpanFilter& filter, double u, double v);

}  // namespace tp::geometry::internal
