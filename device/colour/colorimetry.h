// device/colour/colorimetry.h: spectra to CIE XYZ (D50, 2 degree observer), CIELAB, CIEDE2000
// and sRGB, shared by the simulator's colorimetric printer and the host's proof checks.
#pragma once

#include <array>
#include <cstdint>

namespace tp::device {

/// Spectral sampling of the colour model: 400 .. 700 nm in 20 nm steps.
inline constexpr int kBands = 16;
inline constexpr double kFirstBand_nm = 400;
inline constexpr double kBandStep_nm = 20;
using Spectrum = std::array<double, kBands>;

/// Wavelength of band `i`, nanometres.
constexpr double band_nm(int i) { return kFirstBand_nm + kBandStep_nm * i; }

struct Xyz {
  double x = 0, y = 0, z = 0;  ///< relative to a perfect diffuser (Y = 1), D50
};
struct Lab {
  double l = 0, a = 0, b = 0;
};

/// The ICC D50 white (0.9642, 1, 0.8249).
inline constexpr Xyz kD50White{0.9642, 1.0, 0.8249};

/// Reflectance spectrum (0..1 per band) to XYZ under D50. The CIE 1931 observer is the
/// multi-lobe fit of Wyman, Sloan and Shirley (2013) and D50 a 5003 K Planckian source, scaled
/// (von Kries) so a perfect diffuser gives exactly kD50White.
Xyz spectrum_to_xyz(const Spectrum& reflectance);

/// CIELAB relative to D50.
Lab xyz_to_lab(const Xyz& xyz);
Xyz lab_to_xyz(const Lab& lab);

/// Chromatic adaptation (Bradford, as ICC profiles adapt a media white to D50): the colour `c`
/// seen under `from_white` as it would look under `to_white`.
Xyz adapt_bradford(const Xyz& c, const Xyz& from_white, const Xyz& to_white);

/// CIEDE2000 colour difference (kL = kC = kH = 1).
double delta_e_2000(const Lab& a, const Lab& b);

/// 8-bit sRGB to D50 XYZ (the inverse of xyz_to_srgb8 inside the sRGB gamut).
Xyz srgb8_to_xyz(std::uint8_t r, std::uint8_t g, std::uint8_t b);

/// D50 XYZ to 8-bit sRGB (Bradford-adapted to D65, clipped, sRGB transfer curve).
std::array<std::uint8_t, 3> xyz_to_srgb8(const Xyz& xyz);

}  // namespace tp::device
