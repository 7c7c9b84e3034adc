// geometry/design/raster/mip_image.cpp: builds the premultiplied mip pyramid of a source image.
#include "geometry/design/raster/mip_image.h"

#include <algorithm>
#include <cmath>

#include "geometry/design/internal/srgb.h"

namespace tp::geometry::internal {
namespace {

// A level in linear light, premultiplied, while the pyramid is built.
struct LinearLevel {
  int width = 0, height = 0;
  std::vector<float> rgba;  // 4 floats per texel
  const float* at(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
};

std::uint32_t encode(const float* p) {
  // Back to straight alpha for the sRGB curve, then premultiply the 8-bit codes.
  const float a = std::clamp(p[3], 0.0f, 1.0f);
  if (a <= 0) return 0;
  Rgba8 c;
  c.r = linear_to_srgb8(p[0] / a);
  c.g = linear_to_srgb8(p[1] / a);
  c.b = linear_to_srgb8(p[2] / a);
  c.a = static_cast<std::uint8_t>(std::lround(a * 255.0f));
  return premultiply(c);
}

MipLevel make_level(int width, int height) {
  MipLevel lv;
  lv.width = width;
  lv.height = height;
  lv.stride = width + 3;
  lv.padded.assign(static_cast<size_t>(lv.stride) * (height + 3), 0u);
  return lv;
}

void fill_border(MipLevel& lv, Wrap wrap_u, Wrap wrap_v) {
  // Borders repeat the opposite edges so a bilinear tap at x+1 or y+1 never needs a modulo;
  // along a transparent axis they stay zero.
  std::uint32_t* o = lv.padded.data() + lv.stride + 1;
  for (int y = -1; y <= lv.height + 1; ++y) {
    const bool y_out = y < 0 || y >= lv.height;
    if (y_out && wrap_v == Wrap::kTransparent) continue;
    const int sy = ((y % lv.height) + lv.height) % lv.height;
    for (int x = -1; x <= lv.width + 1; ++x) {
      const bool x_out = x < 0 || x >= lv.width;
      if (!x_out && !y_out) continue;
      if (x_out && wrap_u == Wrap::kTransparent) continue;
      const int sx = ((x % lv.width) + lv.width) % lv.width;
      o[y * lv.stride + x] = o[sy * lv.stride + sx];
    }
  }
}

MipLevel pad(const LinearLevel& lin, Wrap wrap_u, Wrap wrap_v) {
  MipLevel lv = make_level(lin.width, lin.height);
  std::uint32_t* o = lv.padded.data() + lv.stride + 1;
  for (int y = 0; y < lin.height; ++y)
    for (int x = 0; x < lin.width; ++x) o[y * lv.stride + x] = encode(lin.at(x, y));
  fill_border(lv, wrap_u, wrap_v);
  return lv;
}

LinearLevel halve(const LinearLevel& src, Wrap wrap_u, Wrap wrap_v) {
  LinearLevel dst;
  dst.width = std::max(1, (src.width + 1) / 2);
  dst.height = std::max(1, (src.height + 1) / 2);
  dst.rgba.assign(static_cast<size_t>(dst.width) * dst.height * 4, 0.0f);
  // A 2x2 box in linear light; odd sizes wrap (repeat) or see transparency (clamp) at the edge.
  for (int y = 0; y < dst.height; ++y) {
    for (int x = 0; x < dst.width; ++x) {
      float acc[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          int sx = 2 * x + dx, sy = 2 * y + dy;
          if (sx >= src.width) {
            if (wrap_u == Wrap::kTransparent) continue;
            sx %= src.width;
          }
          if (sy >= src.height) {
            if (wrap_v == Wrap::kTransparent) continue;
            sy %= src.height;
          }
          const float* p = src.at(sx, sy);
          for (int k = 0; k < 4; ++k) acc[k] += p[k];
        }
      }
      float* d = &dst.rgba[(static_cast<size_t>(y) * dst.width + x) * 4];
      for (int k = 0; k < 4; ++k) d[k] = acc[k] * 0.25f;
    }
  }
  return dst;
}

}  // namespace

std::uint32_t premultiply(Rgba8 c) {
  const std::uint32_t a = c.a;
  auto mul = [a](std::uint32_t v) { return (v * a + 127) / 255; };
  return mul(c.r) | (mul(c.g) << 8) | (mul(c.b) << 16) | (a << 24);
}

Rgba8 unpremultiply(std::uint32_t t) {
  const std::uint32_t a = t >> 24;
  if (a == 0) return {0, 0, 0, 0};
  auto div = [a](std::uint32_t v) { return static_cast<std::uint8_t>(std::min<std::uint32_t>(255, (v * 255 + a / 2) / a)); };
  return {div(t & 0xFF), div((t >> 8) & 0xFF), div((t >> 16) & 0xFF), static_cast<std::uint8_t>(a)};
}

MipImage::MipImage(const ImageRgba8& image, Wrap wrap_u, Wrap wrap_v) : wrap_u_(wrap_u), wrap_v_(wrap_v) {
  const auto& lut = srgb8_to_linear_table();
  LinearLevel lin;
  lin.width = image.width_px;
  lin.height = image.height_px;
  lin.rgba.resize(static_cast<size_t>(lin.width) * lin.height * 4);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const Rgba8 c = image.pixels[i];
    const float a = c.a / 255.0f;
    if (c.a != 255) opaque_ = false;
    lin.rgba[i * 4 + 0] = lut[c.r] * a;
    lin.rgba[i * 4 + 1] = lut[c.g] * a;
    lin.rgba[i * 4 + 2] = lut[c.b] * a;
    lin.rgba[i * 4 + 3] = a;
  }
  // Level 0 keeps the source codes exactly (no round trip through linear light).
  MipLevel lv0 = make_level(image.width_px, image.height_px);
  std::uint32_t* o = lv0.padded.data() + lv0.stride + 1;
  for (int y = 0; y < lv0.height; ++y)
    for (int x = 0; x < lv0.width; ++x) o[y * lv0.stride + x] = premultiply(image.at(x, y));
  fill_border(lv0, wrap_u, wrap_v);
  levels_.push_back(std::move(lv0));
  while (lin.width > 1 || lin.height > 1) {
    lin = halve(lin, wrap_u, wrap_v);
    levels_.push_back(pad(lin, wrap_u, wrap_v));
  }
}

}  // namespace tp::geometry::internal
