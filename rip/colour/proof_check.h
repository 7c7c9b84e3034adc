// rip/colour/proof_check.h: the independent colour check: a design (or soft proof) image in
// sRGB against the printed fabric's CIELAB image (printsim's fabric-lab.tif, or a scan), CIEDE2000
// over the printed area.
#pragma once

#include <cstddef>
#include <filesystem>

#include "device/colour/colorimetry.h"
#include "rip/common/error.h"

namespace tp::rip {

struct ProofCheckResult {
  std::size_t cells = 0;            ///< printed cells compared (interior of the print: edges left out)
  std::size_t blank_cells = 0;      ///< unprinted cells the fabric white was measured on
  std::size_t edge_cells = 0;       ///< printed cells left out because the design changes colour there
  double cell_mm = 0;
  double mean_de00 = 0, p95_de00 = 0, max_de00 = 0;
  device::Lab bias;                 ///< mean of fabric minus design (L*, a*, b*) over the compared cells
  device::Lab fabric_white;         ///< absolute, as measured on the blank cells
  // With a printer profile: the design's cells the printer cannot reproduce (round trip through
  // the profile, relative colorimetric, off by more than kGamutTolerance_de00) are left out of the
  // figures above and counted here.
  std::size_t out_of_gamut_cells = 0;
  double out_of_gamut_share = 0;    ///< of the printed cells
  double out_of_gamut_worst_de00 = 0;  ///< design against its closest reproducible colour
};

/// Largest design difference between a cell and its neighbours for the cell to be compared.
inline constexpr double kFlatDesign_de00 = 3.0;

/// Round-trip error above which a design colour counts as out of the printer's gamut.
inline constexpr double kGamutTolerance_de00 = 1.0;

/// Compares `design` (8-bit sRGB PNG/TIFF with its resolution; white = unprinted) with
/// `fabric_lab` (3 x float L*, a*, b* D50 with its resolution), both in the roll frame from the
/// same origin. Both are box-averaged in XYZ into square cells of `cell_mm` (the descreening);
/// a cell counts as printed when it and its eight neighbours hold no white design pixel, and is
/// compared when none of those neighbours differs from it by more than kFlatDesign_de00. The
/// fabric is taken media-relative (its blank cells' colour is the design's white), as a
/// relative-colorimetric proof is. Fails with kImage naming the file, or kInvalidArgument when
/// no cell is printed or none is blank.
/// `printer_profile` (optional, an RGB or CMYK output profile) splits out the out-of-gamut cells.
[[nodiscard]] Result<ProofCheckResult> check_proof(const std::filesystem::path& design,
                                                   const std::filesystem::path& fabric_lab, double cell_mm = 1.0,
                                                   const std::filesystem::path& printer_profile = {});

}  // namespace tp::rip
