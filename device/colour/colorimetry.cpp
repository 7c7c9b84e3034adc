// device/colour/colorimetry.cpp: the CIE observer, D50, CIELAB, CIEDE2000 and sRGB encoding.
#include "device/colour/colorimetry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tp::device {

namespace {

// One lobe of the Wyman-Sloan-Shirley fit: a Gaussian with different widths either side.
double lobe(double nm, double mu, double sigma_below, double sigma_above) {
  const double t = (nm - mu) / (nm < mu ? sigma_below : sigma_above);
  return std::exp(-0.5 * t * t);
}

struct Weights {
  Spectrum x{}, y{}, z{};
};

// Illuminant times colour matching functions per band, normalised so a perfect diffuser gives
// kD50White exactly.
Weights make_weights() {
  Weights w;
  double sx = 0, sy = 0, sz = 0;
  for (int i = 0; i < kBands; ++i) {
    const double nm = band_nm(i);
    const double xb = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                      0.065 * lobe(nm, 501.1, 20.4, 26.2);
    const double yb = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
    const double zb = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
    // Planck's law at 5003 K (relative; constants cancel in the normalisation).
    const double m = nm * 1e-9;
    const double planck = 1.0 / (std::pow(m, 5) * (std::exp(1.4388e-2 / (m * 5003.0)) - 1.0));
    w.x[i] = planck * xb;
    w.y[i] = planck * yb;
    w.z[i] = planck * zb;
    sx += w.x[i];
    sy += w.y[i];
    sz += w.z[i];
  }
  for (int i = 0; i < kBands; ++i) {
    w.x[i] *= kD50White.x / sx;
    w.y[i] *= kD50White.y / sy;
    w.z[i] *= kD50White.z / sz;
  }
  return w;
}

const Weights& weights() {
  static const Weights w = make_weights();
  return w;
}

double lab_f(double t) {
  constexpr double e = 216.0 / 24389.0, k = 24389.0 / 27.0;
  return t > e ? std::cbrt(t) : (k * t + 16.0) / 116.0;
}

double lab_f_inv(double f) {
  constexpr double e = 216.0 / 24389.0, k = 24389.0 / 27.0;
  const double t = f * f * f;
  return t > e ? t : (116.0 * f - 16.0) / k;
}

double srgb_encode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

}  // namespace

Xyz srgb8_to_xyz(std::uint8_t r8, std::uint8_t g8, std::uint8_t b8) {
  // Linear sRGB to D50 XYZ, Bradford-adapted (Lindbloom's matrix, the inverse of the one below).
  const double r = srgb_decode(r8 / 255.0), g = srgb_decode(g8 / 255.0), b = srgb_decode(b8 / 255.0);
  return {0.4360747 * r + 0.3850649 * g + 0.1430804 * b, 0.2225045 * r + 0.7168786 * g + 0.0606169 * b,
          0.0139322 * r + 0.0971045 * g + 0.7141733 * b};
}

Xyz spectrum_to_xyz(const Spectrum& r) {
  const Weights& w = weights();
  Xyz o;
  for (int i = 0; i < kBands; ++i) {
    o.x += w.x[i] * r[i];
    o.y += w.y[i] * r[i];
    o.z += w.z[i] * r[i];
  }
  return o;
}

Lab xyz_to_lab(const Xyz& c) {
  const double fx = lab_f(c.x / kD50White.x), fy = lab_f(c.y / kD50White.y), fz = lab_f(c.z / kD50White.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Xyz lab_to_xyz(const Lab& c) {
  const double fy = (c.l + 16.0) / 116.0, fx = fy + c.a / 500.0, fz = fy - c.b / 200.0;
  return {kD50White.x * lab_f_inv(fx), kD50White.y * lab_f_inv(fy), kD50White.z * lab_f_inv(fz)};
}

Xyz adapt_bradford(const Xyz& c, const Xyz& from, const Xyz& to) {
  // Cone-like responses, scaled per cone by the white ratio, and back.
  auto cone = [](const Xyz& v) {
    return std::array<double, 3>{0.8951 * v.x + 0.2664 * v.y - 0.1614 * v.z, -0.7502 * v.x + 1.7135 * v.y + 0.0367 * v.z,
                                 0.0389 * v.x - 0.0685 * v.y + 1.0296 * v.z};
  };
  const auto s = cone(from), d = cone(to), v = cone(c);
  const double r = v[0] * d[0] / s[0], g = v[1] * d[1] / s[1], b = v[2] * d[2] / s[2];
  return {0.9869929 * r - 0.1470543 * g + 0.1599627 * b, 0.4323053 * r + 0.5183603 * g + 0.0492912 * b,
          -0.0085287 * r + 0.0400428 * g + 0.9684867 * b};
}

double delta_e_2000(const Lab& p, const Lab& q) {
  // Sharma, Wu and Dalal (2005), the reference formulation.
  constexpr double pi = std::numbers::pi;
  const double c1 = std::hypot(p.a, p.b), c2 = std::hypot(q.a, q.b);
  const double cm = 0.5 * (c1 + c2);
  const double cm7 = std::pow(cm, 7);
  const double g = 0.5 * (1.0 - std::sqrt(cm7 / (cm7 + 6103515625.0)));
  const double a1 = (1 + g) * p.a, a2 = (1 + g) * q.a;
  const double c1p = std::hypot(a1, p.b), c2p = std::hypot(a2, q.b);
  auto hue = [&](double b, double a) {
    if (a == 0 && b == 0) return 0.0;
    double h = std::atan2(b, a) * 180.0 / pi;
    return h < 0 ? h + 360.0 : h;
  };
  const double h1 = hue(p.b, a1), h2 = hue(q.b, a2);
  const double dl = q.l - p.l, dc = c2p - c1p;
  double dh = 0;
  if (c1p * c2p != 0) {
    dh = h2 - h1;
    if (dh > 180) dh -= 360;
    else if (dh < -180) dh += 360;
  }
  const double dH = 2.0 * std::sqrt(c1p * c2p) * std::sin(dh * pi / 360.0);
  const double lm = 0.5 * (p.l + q.l), cmp = 0.5 * (c1p + c2p);
  double hm = h1 + h2;
  if (c1p * c2p != 0) {
    if (std::abs(h1 - h2) <= 180) hm = 0.5 * (h1 + h2);
    else hm = (h1 + h2 < 360) ? 0.5 * (h1 + h2 + 360) : 0.5 * (h1 + h2 - 360);
  }
  const double t = 1 - 0.17 * std::cos((hm - 30) * pi / 180) + 0.24 * std::cos(2 * hm * pi / 180) +
                   0.32 * std::cos((3 * hm + 6) * pi / 180) - 0.20 * std::cos((4 * hm - 63) * pi / 180);
  const double dtheta = 30 * std::exp(-std::pow((hm - 275) / 25, 2));
  const double cmp7 = std::pow(cmp, 7);
  const double rc = 2 * std::sqrt(cmp7 / (cmp7 + 6103515625.0));
  const double sl = 1 + 0.015 * (lm - 50) * (lm - 50) / std::sqrt(20 + (lm - 50) * (lm - 50));
  const double sc = 1 + 0.045 * cmp, sh = 1 + 0.015 * cmp * t;
  const double rt = -std::sin(2 * dtheta * pi / 180) * rc;
  const double x = dl / sl, y = dc / sc, z = dH / sh;
  return std::sqrt(x * x + y * y + z * z + rt * y * z);
}

std::array<std::uint8_t, 3> xyz_to_srgb8(const Xyz& c) {
  // Bradford D50 -> D65 folded into XYZ -> linear sRGB (Lindbloom's matrix).
  const double r = 3.1338561 * c.x - 1.6168667 * c.y - 0.4906146 * c.z;
  const double g = -0.9787684 * c.x + 1.9161415 * c.y + 0.0334540 * c.z;
  const double b = 0.0719453 * c.x - 0.2289914 * c.y + 1.4052427 * c.z;
  return {static_cast<std::uint8_t>(std::lround(255.0 * srgb_encode(r))),
          static_cast<std::uint8_t>(std::lround(255.0 * srgb_encode(g))),
          static_cast<std::uint8_t>(std::lround(255.0 * srgb_encode(b)))};
}

}  // namespace tp::device
