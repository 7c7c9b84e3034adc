// rip/colour/profile_inverse.h: design colours to the device RGB of an RGB output profile by
// inverting the profile's forward model (A2B) numerically, not through its B2A table.
#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <vector>

#include "device/colour/colorimetry.h"
#include "rip/common/error.h"

namespace tp::rip {

/// An RGB output profile (a calibration set's) inverted at full precision. ArgyllCMS's B2A tables
/// are an inverse sampled on a CIELAB grid: for a textile printer driven through a separation
/// they miss the forward model by about 1.4 dE00 on average (measured on the cotton preset), which
/// is most of what a calibrated print differs from its design. Here each colour starts at the B2A
/// table's answer and a damped Gauss-Newton search over the forward model (box 0..1) takes it to
/// the device value whose predicted colour is nearest in CIELAB: exact inside the gamut, the
/// closest colour (colorimetric clipping) outside it. Relative colorimetric throughout.
class RgbProfileInverse {
 public:
  /// Opens `profile`; fails with kColour naming it if it is not a readable RGB output profile.
  [[nodiscard]] static Result<RgbProfileInverse> open(const std::filesystem::path& profile);
  RgbProfileInverse(RgbProfileInverse&&) noexcept;
  RgbProfileInverse& operator=(RgbProfileInverse&&) noexcept;
  ~RgbProfileInverse();

  /// Device RGB (0..1 each) for each target colour (CIELAB D50, media-relative).
  [[nodiscard]] std::vector<std::array<double, 3>> device_for(const std::vector<device::Lab>& targets) const;
  /// The profile's forward model: media-relative CIELAB D50 for each device RGB (0..1).
  [[nodiscard]] std::vector<device::Lab> colour_of(const std::vector<std::array<double, 3>>& rgb) const;
  /// Device RGB for each 8-bit-style sRGB colour given as 0..1 triples (the design's colours).
  [[nodiscard]] std::vector<std::array<double, 3>> device_for_srgb(
      const std::vector<std::array<double, 3>>& srgb) const;

 private:
  struct Impl;
  explicit RgbProfileInverse(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::rip
