// geometry/continuity/ciede2000.cpp: sRGB -> XYZ -> L*a*b*, and the CIEDE2000 formula.
#include "geometry/continuity/ciede2000.h"

#include <cmath>
#include <numbers>

#include "geometry/common/srgb.h"

namespace tp::geometry {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double k25Pow7 = 6103515625.0;  // 25^7
// D65 reference white of sRGB (Y = 1).
constexpr double kXn = 0.95047, kYn = 1.0, kZn = 1.08883;

double lab_f(double t) {
  constexpr double e = 216.0 / 24389.0, k = 24389.0 / 27.0;
  return t > e ? std::cbrt(t) : (k * t + 16.0) / 116.0;
}

// Hue angle in degrees, 0..360; 0 for achromatic colours.
double hue_deg(double b, double a) {
  if (a == 0 && b == 0) return 0;
  double h = std::atan2(b, a) / kDeg;
  return h < 0 ? h + 360 : h;
}

}  // namespace

Lab srgb_over_white_to_lab(Rgba8 p) {
  const double alpha = p.a / 255.0;
  // Compositing over white happens in linear light, as ink on white fabric mixes light.
  const double r = srgb_to_linear(p.r / 255.0) * alpha + (1 - alpha);
  const double g = srgb_to_linear(p.g / 255.0) * alpha + (1 - alpha);
  const double b = srgb_to_linear(p.b / 255.0) * alpha + (1 - alpha);
  const double x = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
  const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
  const double fx = lab_f(x / kXn), fy = lab_f(y / kYn), fz = lab_f(z / kZn);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

double ciede2000(const Lab& p, const Lab& q) {
  // Chroma with the a* axis stretched for near-neutral colours (the G factor).
  const double c1 = std::hypot(p.a, p.b), c2 = std::hypot(q.a, q.b);
  const double cbar7 = std::pow(0.5 * (c1 + c2), 7);
  const double g = 0.5 * (1 - std::sqrt(cbar7 / (cbar7 + k25Pow7)));
  const double a1 = (1 + g) * p.a, a2 = (1 + g) * q.a;
  const double cp1 = std::hypot(a1, p.b), cp2 = std::hypot(a2, q.b);
  const double h1 = hue_deg(p.b, a1), h2 = hue_deg(q.b, a2);

  const double dl = q.L - p.L, dc = cp2 - cp1;
  double dh = 0;
  if (cp1 * cp2 != 0) {
    dh = h2 - h1;
    if (dh > 180) dh -= 360;
    else if (dh < -180) dh += 360;
  }
  const double dH = 2 * std::sqrt(cp1 * cp2) * std::sin(0.5 * dh * kDeg);

  // Means; the mean hue takes the short way round the circle.
  const double lbar = 0.5 * (p.L + q.L), cbar = 0.5 * (cp1 + cp2);
  double hbar = h1 + h2;
  if (cp1 * cp2 != 0) {
    if (std::abs(h1 - h2) > 180) hbar += hbar < 360 ? 360 : -360;
    hbar *= 0.5;
  }
  const double t = 1 - 0.17 * std::cos((hbar - 30) * kDeg) + 0.24 * std::cos(2 * hbar * kDeg) +
                   0.32 * std::cos((3 * hbar + 6) * kDeg) - 0.20 * std::cos((4 * hbar - 63) * kDeg);
  const double dtheta = 30 * std::exp(-std::pow((hbar - 275) / 25, 2));
  const double cbar_p7 = std::pow(cbar, 7);
  const double rc = 2 * std::sqrt(cbar_p7 / (cbar_p7 + k25Pow7));
  const double l50 = (lbar - 50) * (lbar - 50);
  const double sl = 1 + 0.015 * l50 / std::sqrt(20 + l50);
  const double sc = 1 + 0.045 * cbar;
  const double sh = 1 + 0.015 * cbar * t;
  const double rt = -std::sin(2 * dtheta * kDeg) * rc;
  const double tl = dl / sl, tc = dc / sc, th = dH / sh;
  return std::sqrt(tl * tl + tc * tc + th * th + rt * tc * th);
}

}  // namespace tp::geometry
