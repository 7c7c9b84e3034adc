// simulator/fabric/fabric_colour.cpp: ink densities, level coverages and the factorised
// Yule-Nielsen modified spectral Neugebauer mix.
#include "simulator/fabric/fabric_colour.h"

#include <algorithm>
#include <cmath>

#include "simulator/fabric/fabric_preset.h"

namespace tp::sim {

namespace {

// An absorption band: peak density at `mu_nm`, Gaussian of width `sigma_nm`.
void add_band(Spectrum& d, double peak, double mu_nm, double sigma_nm) {
  for (int i = 0; i < kBands; ++i) {
    const double t = (band_nm(i) - mu_nm) / sigma_nm;
    d[i] += peak * std::exp(-0.5 * t * t);
  }
}

}  // namespace

Spectrum nominal_ink_density(const std::string& name) {
  Spectrum d{};
  auto is = [&](const char* a, const char* b) { return name == a || name == b; };
  if (name == "cyan" || is("light_cyan", "light-cyan")) {
    add_band(d, 1.55, 625, 60);
    add_band(d, 0.18, 470, 45);
    if (name != "cyan") for (double& v : d) v *= 0.32;
  } else if (name == "magenta" || is("light_magenta", "light-magenta")) {
    add_band(d, 1.45, 545, 38);
    add_band(d, 0.22, 420, 30);
    add_band(d, 0.08, 640, 50);
    if (name != "magenta") for (double& v : d) v *= 0.32;
  } else if (name == "yellow") {
    add_band(d, 1.35, 435, 38);
    add_band(d, 0.06, 540, 40);
  } else if (is("black", "light_black") || name == "light-black") {
    for (double& v : d) v = 1.75;
    add_band(d, 0.10, 420, 40);
    if (name != "black") for (double& v : d) v *= 0.3;
  } else if (name == "red") {
    add_band(d, 1.45, 500, 55);
    add_band(d, 0.9, 430, 30);
  } else if (name == "orange") {
    add_band(d, 1.40, 470, 45);
  } else if (name == "green") {
    add_band(d, 1.40, 640, 45);
    add_band(d, 1.20, 430, 40);
  } else if (name == "blue") {
    add_band(d, 1.50, 590, 60);
  } else if (name == "violet") {
    add_band(d, 1.40, 560, 50);
  } else {
    for (double& v : d) v = 0.6;
  }
  return d;
}

Result<FabricColourModel> FabricColourModel::create(const FabricLook& look, int bits_per_pixel) {
  const auto preset = fabric_preset(look.fabric);
  if (!preset)
    return fail(ErrorCode::kInvalidArgument, "fabric '" + look.fabric + "': not a preset (cotton, polyester-satin, silk)");
  const int levels = (1 << std::clamp(bits_per_pixel, 1, 8)) - 1;
  if (look.drop_volume_pl.size() != static_cast<std::size_t>(levels))
    return fail(ErrorCode::kInvalidArgument, "fabric colour: drop_volume_pl needs " + std::to_string(levels) + " levels");
  if (!look.drop_coverage.empty() && look.drop_coverage.size() != static_cast<std::size_t>(levels))
    return fail(ErrorCode::kInvalidArgument, "fabric colour: drop_coverage needs " + std::to_string(levels) + " levels");
  if (!look.ink_strength.empty() && look.ink_strength.size() != look.inks.size())
    return fail(ErrorCode::kInvalidArgument, "fabric colour: ink_strength needs one factor per ink");

  FabricColourModel m;
  m.inks_ = look.inks.size();
  m.n_ = look.yule_nielsen_n > 0 ? look.yule_nielsen_n : preset->yule_nielsen_n;
  m.surface_ = preset->surface_reflectance;
  for (int i = 0; i < kBands; ++i) m.white_root_[i] = std::pow(preset->white[i], 1.0 / m.n_);

  // Coverage per level: as given, or a drop's spot grows as volume^(2/3) and the fabric wicks it.
  std::vector<double> cover(static_cast<std::size_t>(levels));
  const double largest = look.drop_volume_pl.back();
  for (int l = 0; l < levels; ++l) {
    const auto li = static_cast<std::size_t>(l);
    cover[li] = look.drop_coverage.empty()
                    ? std::min(1.0, std::pow(look.drop_volume_pl[li] / largest, 2.0 / 3.0) * 0.92 * preset->drop_spread)
                    : look.drop_coverage[li];
  }
  m.factor_.assign(m.inks_ * kLevelBins, Spectrum{});
  for (std::size_t k = 0; k < m.inks_; ++k) {
    const double strength = look.ink_strength.empty() ? 1.0 : look.ink_strength[k];
    const Spectrum density = nominal_ink_density(look.inks[k]);
    for (int v = 0; v < kLevelBins; ++v) {
      // Up to one full level: a partial spot; beyond it the spot is full and the layer thicker.
      const double a = v == 0 ? 0.0 : v <= levels ? cover[static_cast<std::size_t>(v - 1)] : 1.0;
      const double depth = v <= levels ? 1.0 : static_cast<double>(v) / levels;
      Spectrum& f = m.factor_[k * kLevelBins + static_cast<std::size_t>(v)];
      for (int i = 0; i < kBands; ++i) {
        const double t = std::pow(10.0, -density[i] * strength * preset->ink_uptake * depth);
        f[i] = 1.0 - a + a * std::pow(t, 1.0 / m.n_);
      }
    }
  }
  Spectrum ones;
  ones.fill(1.0);
  m.white_xyz_ = m.finish(ones);
  return m;
}

Xyz FabricColourModel::finish(const Spectrum& product) const {
  Spectrum r{};
  for (int i = 0; i < kBands; ++i) {
    const double body = std::pow(white_root_[i] * product[i], n_);
    r[i] = surface_ + (1.0 - surface_) * body;
  }
  return spectrum_to_xyz(r);
}

Xyz FabricColourModel::area_colour(std::span<const std::uint32_t> counts, std::uint32_t pixels) const {
  Spectrum product;
  product.fill(1.0);
  if (pixels == 0) return white_xyz_;
  bool inked = false;
  const double inv = 1.0 / pixels;
  for (std::size_t k = 0; k < inks_; ++k) {
    const std::uint32_t* c = counts.data() + k * kLevelBins;
    if (c[0] == pixels) continue;  // this ink is absent here
    inked = true;
    Spectrum mean{};
    for (int v = 0; v < kLevelBins; ++v) {
      if (!c[v]) continue;
      const Spectrum& f = factor_[k * kLevelBins + static_cast<std::size_t>(v)];
      const double w = c[v] * inv;
      for (int i = 0; i < kBands; ++i) mean[i] += w * f[i];
    }
    for (int i = 0; i < kBands; ++i) product[i] *= mean[i];
  }
  return inked ? finish(product) : white_xyz_;
}

Xyz FabricColourModel::pixel_colour(std::span<const std::uint8_t> levels) const {
  Spectrum product;
  product.fill(1.0);
  for (std::size_t k = 0; k < inks_ && k < levels.size(); ++k) {
    if (!levels[k]) continue;
    const Spectrum& f = factor_[k * kLevelBins + static_cast<std::size_t>(bin(levels[k]))];
    for (int i = 0; i < kBands; ++i) product[i] *= f[i];
  }
  return finish(product);
}

}  // namespace tp::sim
