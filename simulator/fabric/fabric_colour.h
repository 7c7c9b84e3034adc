// simulator/fabric/fabric_colour.h: the colorimetric printer: what colour the drops of each ink
// and level give on a fabric, mixed by the Yule-Nielsen modified spectral Neugebauer model.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "simulator/common/error.h"
#include "device/colour/colorimetry.h"
#include "simulator/fabric/fabric_preset.h"

namespace tp::sim {

/// What the colour model needs from the printer model (device::PrinterModel's colour fields).
struct FabricLook {
  std::string fabric = "cotton";          ///< preset name (simulator/fabric/fabric_preset.h)
  std::vector<std::string> inks;          ///< channel names; the nominal colour comes from the name
  std::vector<double> ink_strength;       ///< per ink, empty = all 1
  std::vector<double> drop_volume_pl{4, 8, 12};
  std::vector<double> drop_coverage;      ///< per level, empty = from volumes and the fabric's spread
  double yule_nielsen_n = 0;              ///< 0 = the fabric's
};

/// Spectral Neugebauer primaries made by overprinting (each ink a filter over the fabric), so the
/// Yule-Nielsen sum over the 2^inks Demichel weights factorises into one term per ink:
///   R^(1/n) = W^(1/n) * prod_k (1 - a_k + a_k T_k^(1/n)),   R_measured = s + (1 - s) R
/// with W the fabric white, T_k the ink's transmittance (double pass), a_k its area coverage and
/// s the surface reflection. A pixel holding more than one full drop level (passes overlapping)
/// deepens the ink's density in proportion.
class FabricColourModel {
 public:
  /// Summed drop levels are binned 0 .. kLevelBins - 1 (higher sums share the last bin).
  static constexpr int kLevelBins = 16;

  /// Fails with kInvalidArgument naming the field (unknown fabric, wrong number of coverages).
  [[nodiscard]] static Result<FabricColourModel> create(const FabricLook& look, int bits_per_pixel);

  std::size_t inks() const { return inks_; }
  /// Colour of an area from a histogram of summed drop levels: `counts` holds inks() x
  /// kLevelBins pixel counts (ink-major), each ink's row summing to `pixels`.
  Xyz area_colour(std::span<const std::uint32_t> counts, std::uint32_t pixels) const;
  /// Colour of one pixel from its summed drop level per ink.
  Xyz pixel_colour(std::span<const std::uint8_t> levels) const;
  /// The bare fabric.
  const Xyz& fabric_white() const { return white_xyz_; }
  /// The level bin of a summed drop level.
  static int bin(unsigned level) { return level < kLevelBins ? static_cast<int>(level) : kLevelBins - 1; }

 private:
  Xyz finish(const Spectrum& product) const;

  std::size_t inks_ = 0;
  double n_ = 2, surface_ = 0;
  Spectrum white_root_{};                          ///< W^(1/n)
  std::vector<Spectrum> factor_;                   ///< inks x kLevelBins: 1 - a + a T^(m/n)
  Xyz white_xyz_;
};

/// Nominal optical density (reflection, double pass) of a solid of the ink called `name` per band;
/// unknown names get a neutral grey.
Spectrum nominal_ink_density(const std::string& name);

}  // namespace tp::sim
