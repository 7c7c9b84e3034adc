// rip/colour/profile_inverse.cpp: the B2A start and the damped Gauss-Newton search over an RGB
// output profile's forward model, batched through lcms2.
#include "rip/colour/profile_inverse.h"

#include <lcms2.h>

#include <algorithm>
#include <cmath>

#include "rip/colour/internal/lcms_handles.h"

namespace tp::rip {

namespace {

/// Added to the normal equations' diagonal so a flat direction of the model never makes them singular.
constexpr double kRidge = 1e-9;

using Rgb = std::array<double, 3>;

// Search settings: the forward model is a table interpolated piecewise linearly, so a few steps
// reach its exact inverse. lcms2 evaluates 16-bit tables at 16-bit precision in and out (CIELAB
// steps of about 0.004), so the Jacobian's step is some 260 input units: its slopes are then
// good to about 1 %, while still inside one cell of a 33-point grid.
constexpr int kMaxSteps = 24;
constexpr double kJacobianStep = 4e-3;
constexpr double kConverged_de2 = 1e-6;  // squared CIELAB distance (dE76 0.001)

double dist2(const device::Lab& a, const device::Lab& b) {
  const double dl = a.l - b.l, da = a.a - b.a, db = a.b - b.b;
  return dl * dl + da * da + db * db;
}

// Solves the 3 x 3 system m x = v (Cramer); false when it is singular.
bool solve3(const double m[3][3], const double v[3], double x[3]) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (!(std::abs(det) > 1e-300)) return false;
  for (int c = 0; c < 3; ++c) {
    double k[3][3];
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < 3; ++j) k[r][j] = j == c ? v[r] : m[r][j];
    x[c] = (k[0][0] * (k[1][1] * k[2][2] - k[1][2] * k[2][1]) - k[0][1] * (k[1][0] * k[2][2] - k[1][2] * k[2][0]) +
            k[0][2] * (k[1][0] * k[2][1] - k[1][1] * k[2][0])) /
           det;
  }
  return true;
}

}  // namespace

struct RgbProfileInverse::Impl {
  lcms::Transform forward;   // device RGB double (0..1) -> Lab double, relative colorimetric
  lcms::Transform backward;  // Lab double -> device RGB double: the profile's B2A, the start
  lcms::Transform srgb_lab;  // sRGB double -> Lab double (D65 to D50 by the profile's Bradford)

  std::vector<device::Lab> eval(const std::vector<Rgb>& rgb) const {
    std::vector<cmsCIELab> out(rgb.size());
    if (!rgb.empty()) cmsDoTransform(forward.get(), rgb.data(), out.data(), static_cast<cmsUInt32Number>(rgb.size()));
    std::vector<device::Lab> lab(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) lab[i] = {out[i].L, out[i].a, out[i].b};
    return lab;
  }
};

RgbProfileInverse::RgbProfileInverse(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RgbProfileInverse::RgbProfileInverse(RgbProfileInverse&&) noexcept = default;
RgbProfileInverse& RgbProfileInverse::operator=(RgbProfileInverse&&) noexcept = default;
RgbProfileInverse::~RgbProfileInverse() = default;

Result<RgbProfileInverse> RgbProfileInverse::open(const std::filesystem::path& profile) {
  lcms::install_error_handler();
  const std::string name = profile.string();
  lcms::Profile prof(cmsOpenProfileFromFile(name.c_str(), "r"));
  if (!prof) return fail(ErrorCode::kColour, name + ": not a readable ICC profile");
  if (cmsGetDeviceClass(prof.get()) != cmsSigOutputClass || cmsGetColorSpace(prof.get()) != cmsSigRgbData)
    return fail(ErrorCode::kColour, name + ": a calibration profile must be an RGB output profile");
  lcms::Profile lab(cmsCreateLab4Profile(nullptr)), srgb(cmsCreate_sRGBProfile());
  const cmsUInt32Number flags = cmsFLAGS_NOOPTIMIZE | cmsFLAGS_NOCACHE;
  auto impl = std::make_unique<Impl>();
  impl->forward.reset(
      cmsCreateTransform(prof.get(), TYPE_RGB_DBL, lab.get(), TYPE_Lab_DBL, INTENT_RELATIVE_COLORIMETRIC, flags));
  impl->backward.reset(
      cmsCreateTransform(lab.get(), TYPE_Lab_DBL, prof.get(), TYPE_RGB_DBL, INTENT_RELATIVE_COLORIMETRIC, flags));
  impl->srgb_lab.reset(
      cmsCreateTransform(srgb.get(), TYPE_RGB_DBL, lab.get(), TYPE_Lab_DBL, INTENT_RELATIVE_COLORIMETRIC, flags));
  if (!impl->forward || !impl->backward || !impl->srgb_lab)
    return fail(ErrorCode::kColour, name + ": lcms2 cannot build its forward and inverse transforms");
  return RgbProfileInverse(std::move(impl));
}

std::vector<device::Lab> RgbProfileInverse::colour_of(const std::vector<Rgb>& rgb) const { return impl_->eval(rgb); }

std::vector<Rgb> RgbProfileInverse::device_for_srgb(const std::vector<Rgb>& srgb) const {
  std::vector<cmsCIELab> lab(srgb.size());
  if (!srgb.empty())
    cmsDoTransform(impl_->srgb_lab.get(), srgb.data(), lab.data(), static_cast<cmsUInt32Number>(srgb.size()));
  std::vector<device::Lab> targets(srgb.size());
  for (std::size_t i = 0; i < srgb.size(); ++i) targets[i] = {lab[i].L, lab[i].a, lab[i].b};
  return device_for(targets);
}

std::vector<Rgb> RgbProfileInverse::device_for(const std::vector<device::Lab>& targets) const {
  const std::size_t n = targets.size();
  std::vector<Rgb> x(n);
  if (n == 0) return x;
  // The start: the profile's own inverse table, inside the box.
  std::vector<cmsCIELab> in(n);
  for (std::size_t i = 0; i < n; ++i) in[i] = {targets[i].l, targets[i].a, targets[i].b};
  cmsDoTransform(impl_->backward.get(), in.data(), x.data(), static_cast<cmsUInt32Number>(n));
  for (Rgb& v : x)
    for (double& c : v) c = std::isfinite(c) ? std::clamp(c, 0.0, 1.0) : 0.5;
  std::vector<device::Lab> f = impl_->eval(x);
  std::vector<double> err(n), damping(n, 1e-3);
  for (std::size_t i = 0; i < n; ++i) err[i] = dist2(f[i], targets[i]);

  // Damped Gauss-Newton (Levenberg-Marquardt) on the colours not yet reached, all in one batch.
  std::vector<std::size_t> active;
  for (std::size_t i = 0; i < n; ++i)
    if (err[i] > kConverged_de2) active.push_back(i);
  for (int step = 0; step < kMaxSteps && !active.empty(); ++step) {
    const std::size_t m = active.size();
    std::vector<Rgb> probe(3 * m);
    std::vector<double> h(3 * m);
    for (std::size_t k = 0; k < m; ++k)
      for (int c = 0; c < 3; ++c) {
        Rgb p = x[active[k]];
        const double d = p[c] + kJacobianStep <= 1.0 ? kJacobianStep : -kJacobianStep;
        p[c] += d;
        probe[3 * k + c] = p;
        h[3 * k + c] = d;
      }
    const std::vector<device::Lab> fp = impl_->eval(probe);
    std::vector<Rgb> cand(m);
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t i = active[k];
      double j[3][3];  // j[row: L, a, b][column: R, G, B]
      for (int c = 0; c < 3; ++c) {
        const device::Lab& q = fp[3 * k + c];
        j[0][c] = (q.l - f[i].l) / h[3 * k + c];
        j[1][c] = (q.a - f[i].a) / h[3 * k + c];
        j[2][c] = (q.b - f[i].b) / h[3 * k + c];
      }
      const double r[3] = {f[i].l - targets[i].l, f[i].a - targets[i].a, f[i].b - targets[i].b};
      double a[3][3], g[3], d[3];
      for (int p = 0; p < 3; ++p) {
        g[p] = -(j[0][p] * r[0] + j[1][p] * r[1] + j[2][p] * r[2]);
        for (int q = 0; q < 3; ++q) a[p][q] = j[0][p] * j[0][q] + j[1][p] * j[1][q] + j[2][p] * j[2][q];
      }
      for (int p = 0; p < 3; ++p) a[p][p] += damping[i] * a[p][p] + kRidge;
      cand[k] = x[i];
      if (solve3(a, g, d))
        for (int c = 0; c < 3; ++c) cand[k][c] = std::clamp(x[i][c] + d[c], 0.0, 1.0);
    }
    const std::vector<device::Lab> fc = impl_->eval(cand);
    std::vector<std::size_t> still;
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t i = active[k];
      const double e = dist2(fc[k], targets[i]);
      const double gain = err[i] - e;
      if (gain > 0) {
        x[i] = cand[k];
        f[i] = fc[k];
        err[i] = e;
        damping[i] = std::max(1e-6, damping[i] / 3);
      } else {
        damping[i] *= 4;
      }
      // Reached, or no longer moving (on the gamut's surface: the closest colour is found).
      if (err[i] > kConverged_de2 && (gain > 1e-6 * err[i] || (gain <= 0 && damping[i] < 1e3))) still.push_back(i);
    }
    active = std::move(still);
  }
  return x;
}

}  // namespace tp::rip
