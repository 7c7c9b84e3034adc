// host/bench/textured_piece_renderer.cpp: span-based rendering of textured convex pieces (fixed-point
// bilinear texture steps along each row, per-pixel coverage only near edges).
#include "host/bench/textured_piece_renderer.h"
#include "geometry/common/tolerances.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace tp::rip {

namespace {

using geometry::Rgba8;
using geometry::Vec2;

/// A pixel counts as fully inside when its centre is this many pixel sizes from every edge.
constexpr double kInteriorDistancePx = 0.7072;  // half the diagonal: the whole pixel is inside
constexpr int kFixedShift = 16;                 ///< texture coordinates in 16.16 fixed point

/// src-over of straight-alpha colours.
inline Rgba8 over(Rgba8 src, Rgba8 dst) {
  if (src.a == 255 || dst.a == 0) return src;
  if (src.a == 0) return dst;
  const unsigned sa = src.a, da = dst.a * (255u - sa) / 255u, a = sa + da;
  auto mix = [&](unsigned s, unsigned d) { return static_cast<std::uint8_t>((s * sa + d * da + a / 2) / a); };
  return {mix(src.r, dst.r), mix(src.g, dst.g), mix(src.b, dst.b), static_cast<std::uint8_t>(a)};
}

/// Bilinear texel fetch at 16.16 coordinates already wrapped into the texture: first along x
/// (8-bit weights, 16-bit result halved), then along y, rounded once at the end.
inline Rgba8 bilinear(const geometry::ImageRgba8& tex, std::int64_t u, std::int64_t v) {
  const int w = tex.width_px, h = tex.height_px;
  const int x0 = static_cast<int>(u >> kFixedShift), y0 = static_cast<int>(v >> kFixedShift);
  const int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
  const int fx = static_cast<int>(u >> 8) & 255, fy = static_cast<int>(v >> 8) & 255;
  const Rgba8* r0 = tex.pixels.data() + static_cast<size_t>(y0) * w;
  const Rgba8* r1 = tex.pixels.data() + static_cast<size_t>(y1) * w;
#if defined(__SSE2__)
  std::uint32_t a, b, c, d;
  std::memcpy(&a, r0 + x0, 4);
  std::memcpy(&b, r0 + x1, 4);
  std::memcpy(&c, r1 + x0, 4);
  std::memcpy(&d, r1 + x1, 4);
  const __m128i zero = _mm_setzero_si128();
  const __m128i wx = _mm_set1_epi32((256 - fx) | (fx << 16));
  const __m128i wy = _mm_set1_epi32((256 - fy) | (fy << 16));
  // (a, b) channel pairs as int16, madd: a * (256 - fx) + b * fx per channel; same for (c, d).
  const __m128i ab = _mm_unpacklo_epi8(_mm_unpacklo_epi8(_mm_cvtsi32_si128(static_cast<int>(a)), _mm_cvtsi32_si128(static_cast<int>(b))), zero);
  const __m128i cd = _mm_unpacklo_epi8(_mm_unpacklo_epi8(_mm_cvtsi32_si128(static_cast<int>(c)), _mm_cvtsi32_si128(static_cast<int>(d))), zero);
  const __m128i top = _mm_srli_epi32(_mm_madd_epi16(ab, wx), 1), bottom = _mm_srli_epi32(_mm_madd_epi16(cd, wx), 1);
  // (top, bottom) pairs as int16 (<= 32640), madd with the y weights, round, narrow to bytes.
  const __m128i tb = _mm_packs_epi32(_mm_unpacklo_epi32(top, bottom), _mm_unpackhi_epi32(top, bottom));
  __m128i acc = _mm_madd_epi16(tb, wy);
  acc = _mm_srli_epi32(_mm_add_epi32(acc, _mm_set1_epi32(1 << 14)), 15);
  const __m128i px16 = _mm_packs_epi32(acc, acc);
  const std::uint32_t px = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_packus_epi16(px16, px16)));
  return {static_cast<std::uint8_t>(px), static_cast<std::uint8_t>(px >> 8), static_cast<std::uint8_t>(px >> 16),
          static_cast<std::uint8_t>(px >> 24)};
#else
  const Rgba8 a = r0[x0], b = r0[x1], c = r1[x0], d = r1[x1];
  auto mix = [&](int p, int q, int r, int s) {
    const int top = (p * (256 - fx) + q * fx) >> 1, bottom = (r * (256 - fx) + s * fx) >> 1;
    return static_cast<std::uint8_t>((top * (256 - fy) + bottom * fy + (1 << 14)) >> 15);
  };
  return {mix(a.r, b.r, c.r, d.r), mix(a.g, b.g, c.g, d.g), mix(a.b, b.b, c.b, d.b), mix(a.a, b.a, c.a, d.a)};
#endif
}

inline std::int64_t wrap(std::int64_t v, std::int64_t period) {
  v %= period;
  return v < 0 ? v + period : v;
}

}  // namespace

void TexturedPieceRenderer::render(int piece, const geometry::Affine2& m, int width_px, int height_px, Rgba8* out,
                                   std::ptrdiff_t row_stride_px) const {
  const Piece& pc = pieces_[piece];
  const geometry::ImageRgba8& tex = *pc.texture;
  const geometry::Polygon& poly = pc.outline_mm;
  const size_t ne = poly.size();
  // Piece mm spanned by one pixel, for converting edge distances to pixels.
  const double px_mm = std::sqrt(std::abs(m.determinant()));
  if (ne < 3 || !(px_mm > 0) || tex.width_px <= 0 || tex.height_px <= 0) return;

  // Signed distance (pixels, > 0 inside) of pixel centre (i + 0.5, j + 0.5) to edge e is
  // alpha_e(j) + beta_e * i: affine along the row.
  struct EdgeLine {
    double beta, gamma, alpha0;  ///< distance = alpha0 + gamma * (j + 0.5) + beta * (i + 0.5)
  };
  std::vector<EdgeLine> edges(ne);
  for (size_t e = 0; e < ne; ++e) {
    const Vec2 a = poly[e], b = poly[(e + 1) % ne];
    const Vec2 n = geometry::perp(geometry::normalized(b - a));  // inward normal for CCW
    // d(p) = dot(n, p - a); p = m(x, y) = (m.a x + m.b y + m.c, m.d x + m.e y + m.f)
    edges[e].beta = (n.x * m.a + n.y * m.d) / px_mm;
    edges[e].gamma = (n.x * m.b + n.y * m.e) / px_mm;
    edges[e].alpha0 = (n.x * (m.c - a.x) + n.y * (m.f - a.y)) / px_mm;
  }
  const double tex_scale = pc.texture_px_per_mm * (1 << kFixedShift);
  const std::int64_t period_u = static_cast<std::int64_t>(tex.width_px) << kFixedShift;
  const std::int64_t period_v = static_cast<std::int64_t>(tex.height_px) << kFixedShift;
  const auto du = static_cast<std::int64_t>(std::llround(m.a * tex_scale));
  const auto dv = static_cast<std::int64_t>(std::llround(m.d * tex_scale));
  // Half a texel: bilinear weights are centred on texel centres.
  const double half_texel = 0.5 * (1 << kFixedShift);

  for (int j = 0; j < height_px; ++j) {
    const double yc = j + 0.5;
    // Columns whose centre is inside every half-plane by > -0.5 px (touched) and by > the
    // interior distance (full coverage).
    // Bounds are inclusive, in pixel index units.
    double touch_lo = 0, touch_hi = width_px - 1, full_lo = 0, full_hi = width_px - 1;
    for (const EdgeLine& e : edges) {
      const double base = e.alpha0 + e.gamma * yc;  // distance at i + 0.5 = 0
      auto clip = [&](double threshold, double& lo, double& hi) {
        // base + beta * x >= threshold, x = i + 0.5
        if (std::abs(e.beta) < geometry::kParallelDeterminant) {
          if (base < threshold) lo = hi + 1;
          return;
        }
        const double x = (threshold - base) / e.beta;
        if (e.beta > 0) lo = std::max(lo, x - 0.5);
        else hi = std::min(hi, x - 0.5);
      };
      clip(-0.5, touch_lo, touch_hi);
      clip(kInteriorDistancePx, full_lo, full_hi);
    }
    const int i0 = std::max(0, static_cast<int>(std::ceil(touch_lo)));
    if (touch_hi < touch_lo) continue;
    const int i1 = std::min(width_px, static_cast<int>(std::floor(touch_hi)) + 1);
    if (i0 >= i1) continue;
    const int f0 = std::clamp(static_cast<int>(std::ceil(full_lo)), i0, i1);
    const int f1 = full_hi < full_lo ? f0 : std::clamp(static_cast<int>(std::floor(full_hi)) + 1, f0, i1);

    Rgba8* row = out + static_cast<std::ptrdiff_t>(j) * row_stride_px;
    // Texture coordinates of the first touched pixel's centre, then exact steps along the row.
    const Vec2 q = m.apply({i0 + 0.5, yc});
    std::int64_t u = wrap(static_cast<std::int64_t>(std::llround((q.x - pc.texture_origin_mm.x) * tex_scale - half_texel)), period_u);
    std::int64_t v = wrap(static_cast<std::int64_t>(std::llround((q.y - pc.texture_origin_mm.y) * tex_scale - half_texel)), period_v);
    const std::int64_t du_w = wrap(du, period_u), dv_w = wrap(dv, period_v);
    for (int i = i0; i < i1; ++i) {
      Rgba8 c = bilinear(tex, u, v);
      if (i < f0 || i >= f1) {
        // Edge pixel: coverage from the nearest edge, a linear ramp one pixel wide.
        double d = 1e9;
        for (const EdgeLine& e : edges) d = std::min(d, e.alpha0 + e.gamma * yc + e.beta * (i + 0.5));
        const double cov = std::clamp(d + 0.5, 0.0, 1.0);
        c.a = static_cast<std::uint8_t>(std::lround(c.a * cov));
        row[i] = over(c, row[i]);
      } else if (c.a == 255 || row[i].a == 0) {
        row[i] = c;
      } else {
        row[i] = over(c, row[i]);
      }
      u += du_w;
      if (u >= period_u) u -= period_u;
      v += dv_w;
      if (v >= period_v) v -= period_v;
    }
  }
}

}  // namespace tp::rip
