// geometry/design/textures.cpp: periodic value noise, marbling, stripes and the rosette motif.
#include "geometry/design/textures.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Hash of a lattice point to 0..1 (integer mixing; deterministic across platforms).
double lattice(int x, int y, std::uint32_t seed) {
  std::uint32_t h = static_cast<std::uint32_t>(x) * 0x8da6b343u ^ static_cast<std::uint32_t>(y) * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xFFFFFF) / static_cast<double>(0xFFFFFF);
}

// Smooth value noise with lattice period (px, py): tileable over one period.
double periodic_noise(double x, double y, int px, int py, std::uint32_t seed) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
  auto at = [&](int i, int j) { return lattice(((i % px) + px) % px, ((j % py) + py) % py, seed); };
  const double a = at(x0, y0), b = at(x0 + 1, y0), c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
  return (a * (1 - sx) + b * sx) * (1 - sy) + (c * (1 - sx) + d * sx) * sy;
}

// Fractal sum of periodic octaves over the unit tile (u, v in 0..1).
double fbm(double u, double v, std::uint32_t seed) {
  double sum = 0, amp = 0.5;
  int period = 4;
  for (int o = 0; o < 5; ++o) {
    sum += amp * periodic_noise(u * period, v * period, period, period, seed + static_cast<std::uint32_t>(o) * 101u);
    amp *= 0.5;
    period *= 2;
  }
  return sum;
}

Rgba8 mix(Rgba8 a, Rgba8 b, double t) {
  auto m = [t](std::uint8_t x, std::uint8_t y) { return static_cast<std::uint8_t>(std::lround(x + (y - x) * t)); };
  return {m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), m(a.a, b.a)};
}

ImageRgba8 blank(int w, int h) {
  ImageRgba8 img;
  img.width_px = std::max(1, w);
  img.height_px = std::max(1, h);
  img.pixels.assign(static_cast<size_t>(img.width_px) * img.height_px, Rgba8{});
  return img;
}

}  // namespace

ImageRgba8 marbling(const MarblingOptions& o) {
  ImageRgba8 img = blank(o.width_px, o.height_px);
  img.source = "procedural:marbling";
  const auto& pal = o.palette.empty() ? MarblingOptions{}.palette : o.palette;
  const int n = static_cast<int>(pal.size());
  for (int y = 0; y < img.height_px; ++y) {
    for (int x = 0; x < img.width_px; ++x) {
      const double u = (x + 0.5) / img.width_px, v = (y + 0.5) / img.height_px;
      // Domain warp twice (the swirl), then diagonal bands through the palette.
      const double w1 = fbm(u, v, o.seed), w2 = fbm(u + 0.37, v + 0.61, o.seed + 7);
      const double warp = o.turbulence * (fbm(u + 0.8 * w1, v + 0.8 * w2, o.seed + 13) - 0.5);
      const double phase = kTwoPi * (o.bands * u + o.bands * v) + 2 * kTwoPi * warp;
      const double t = 0.5 + 0.5 * std::sin(phase);
      const double pos = t * (n - 1);
      const int i = std::min(n - 2, static_cast<int>(pos));
      const double f = pos - i;
      // Sharpen transitions a little: marbled veins have crisp edges.
      const double s = f * f * (3 - 2 * f);
      img.at(x, y) = n == 1 ? pal[0] : mix(pal[static_cast<size_t>(i)], pal[static_cast<size_t>(i + 1)], s);
    }
  }
  return img;
}

ImageRgba8 stripes(int w, int h, int count, bool vertical, const std::vector<Rgba8>& colours) {
  ImageRgba8 img = blank(w, h);
  img.source = "procedural:stripes";
  if (colours.empty() || count <= 0) return img;
  const int len = vertical ? img.width_px : img.height_px;
  const double period = static_cast<double>(len) / count;
  for (int i = 0; i < len; ++i) {
    // Box filter over the pixel: the fraction of it in each stripe.
    const double a = i / period, b = (i + 1) / period;
    const int sa = static_cast<int>(std::floor(a));
    Rgba8 c = colours[static_cast<size_t>(sa % static_cast<int>(colours.size()))];
    if (std::floor(b) > sa && b - std::floor(b) > kCeilSlack) {
      const Rgba8 next = colours[static_cast<size_t>((sa + 1) % static_cast<int>(colours.size()))];
      c = mix(c, next, (b - std::floor(b)) / (b - a));
    }
    for (int k = 0; k < (vertical ? img.height_px : img.width_px); ++k) {
      if (vertical) img.at(i, k) = c;
      else img.at(k, i) = c;
    }
  }
  return img;
}

ImageRgba8 placement_motif(int size_px, Rgba8 petal, Rgba8 centre) {
  ImageRgba8 img = blank(size_px, size_px);
  img.source = "procedural:motif";
  const double c = 0.5 * img.width_px, R = 0.48 * img.width_px;
  constexpr int kSub = 4;  // 4 x 4 supersampling for anti-aliased petal edges
  for (int y = 0; y < img.height_px; ++y) {
    for (int x = 0; x < img.width_px; ++x) {
      double petal_cov = 0, centre_cov = 0, shade = 0;
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          const double px = x + (sx + 0.5) / kSub - c, py = y + (sy + 0.5) / kSub - c;
          const double r = std::hypot(px, py), th = std::atan2(py, px);
          const double edge = R * (0.55 + 0.45 * std::abs(std::cos(3 * th)));
          if (r < 0.22 * R) centre_cov += 1;
          else if (r < edge) {
            petal_cov += 1;
            shade += r / edge;
          }
        }
      const double total = kSub * kSub;
      const double a = (petal_cov + centre_cov) / total;
      if (a <= 0) continue;
      // Petals darken towards their tips; the centre is flat.
      Rgba8 pc = petal_cov > 0 ? mix(petal, Rgba8{60, 10, 30, 255}, 0.6 * shade / petal_cov) : petal;
      Rgba8 col = centre_cov > 0 ? mix(pc, centre, centre_cov / (petal_cov + centre_cov)) : pc;
      col.a = static_cast<std::uint8_t>(std::lround(a * 255));
      img.at(x, y) = col;
    }
  }
  return img;
}

}  // namespace tp::geometry
