// geometry/design/raster/mip_image.h: a source image as a premultiplied sRGB mip pyramid with
// padded borders, so the renderer's span samplers never branch on image edges.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/common/image.h"

namespace tp::geometry::internal {

/// How texture coordinates outside [0, size) behave.
enum class Wrap { kRepeat, kTransparent };

/// One level: width x height texels plus a border of 1 texel left/top and 2 right/bottom.
/// Texel (x, y) for x in [-1, w+1], y in [-1, h+1] is at `origin()[y * stride + x]`.
/// Along a repeating axis the border copies the opposite edge; along a transparent one it is zero.
struct MipLevel {
  int width = 0;
  int height = 0;
  int stride = 0;                     ///< texels per padded row (width + 3)
  std::vector<std::uint32_t> padded;  ///< premultiplied sRGB8, bytes R,G,B,A (little-endian)

  const std::uint32_t* origin() const { return padded.data() + stride + 1; }
};

/// An image ready for filtered sampling: level 0 is the source, each next level halves it,
/// down to 1x1, filtered in linear light with premultiplied alpha.
class MipImage {
 public:
  /// Builds the pyramid; the image must be non-empty (the caller checks).
  MipImage(const ImageRgba8& image, Wrap wrap_u, Wrap wrap_v);

  int level_count() const { return static_cast<int>(levels_.size()); }
  const MipLevel& level(int i) const { return levels_[static_cast<size_t>(i)]; }
  Wrap wrap_u() const { return wrap_u_; }
  Wrap wrap_v() const { return wrap_v_; }
  int width() const { return levels_.front().width; }
  int height() const { return levels_.front().height; }
  /// True when every texel of the source is fully opaque.
  bool opaque() const { return opaque_; }

 private:
  std::vector<MipLevel> levels_;
  Wrap wrap_u_, wrap_v_;
  bool opaque_ = true;
};

/// Packs straight-alpha sRGB into the premultiplied texel format.
std::uint32_t premultiply(Rgba8 c);

/// Unpacks a premultiplied texel to straight alpha (the division the compositor needs).
Rgba8 unpremultiply(std::uint32_t texel);

/// Linear interpolation of two packed texels, weight `f` of `q` in 0..256 (rounded).
inline std::uint32_t lerp_texel(std::uint32_t p, std::uint32_t q, std::uint32_t f) {
  const std::uint32_t g = 256 - f;
  const std::uint32_t rb = ((((p & 0xFF00FFu) * g + (q & 0xFF00FFu) * f) + 0x800080u) >> 8) & 0xFF00FFu;
  const std::uint32_t ag = ((((p >> 8) & 0xFF00FFu) * g + ((q >> 8) & 0xFF00FFu) * f) + 0x800080u) & 0xFF00FF00u;
  return rb | ag;
}

/// Scales a packed premultiplied texel by `f` in 0..256.
inline std::uint32_t scale_texel(std::uint32_t p, std::uint32_t f) {
  const std::uint32_t rb = ((((p & 0xFF00FFu) * f) + 0x800080u) >> 8) & 0xFF00FFu;
  const std::uint32_t ag = ((((p >> 8) & 0xFF00FFu) * f) + 0x800080u) & 0xFF00FF00u;
  return rb | ag;
}

/// Premultiplied src-over: src + dst * (1 - src alpha).
inline std::uint32_t over_texel(std::uint32_t src, std::uint32_t dst) {
  const std::uint32_t inv = 256 - ((src >> 24) + ((src >> 24) >> 7));  // 255 -> 0, 0 -> 256
  const std::uint32_t d = scale_texel(dst, inv);
  // Channels cannot overflow: premultiplied src channel <= src alpha, and d <= 1 - src alpha.
  return src + d;
}

}  // namespace tp::geometry::internal
