// rip/colour/soft_proof.h: a design as the printer will reproduce it: through the printer
// profile and back (relative colorimetric), with an out-of-gamut overlay and gamut figures.
#pragma once

#include <filesystem>

#include "geometry/common/image.h"
#include "rip/common/error.h"

namespace tp::rip {

struct SoftProofSummary {
  std::size_t printed_pixels = 0;     ///< design pixels with any opacity, not white
  double out_of_gamut_share = 0;      ///< of those, off by more than kGamutTolerance_de00
  double worst_de00 = 0;              ///< design against its proof, worst pixel
};

/// Renders `design` (sRGB) through `profile` (a printer output profile, any channel count):
/// `proof` gets the colours the printer gives (unprinted pixels unchanged), and `overlay`, if not
/// null, the proof with out-of-gamut pixels marked in pure green. Fails (kColour) naming the
/// profile when lcms2 cannot use it.
[[nodiscard]] Result<SoftProofSummary> soft_proof(const geometry::ImageRgba8& design, const std::filesystem::path& profile,
                                                  geometry::ImageRgba8& proof, geometry::ImageRgba8* overlay);

}  // namespace tp::rip
