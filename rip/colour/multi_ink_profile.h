// rip/colour/multi_ink_profile.h: builds an ICC output profile for a printer with any set of inks
// (CMYK, or CMYK plus red, orange, blue, green, violet) from the colours of its solid inks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rip/common/error.h"

namespace tp::rip {

/// The colour of one ink printed solid on the fabric (CIELAB, D50).
struct InkSolid {
  std::string name;
  double L = 50, a = 0, b = 0;
};

/// What to build the profile from.
struct MultiInkProfileSpec {
  std::vector<InkSolid> inks;   ///< in channel order; chromatic inks must differ in hue
  double paper_L = 95, paper_a = 0, paper_b = -2;  ///< the unprinted fabric
  int separation_grid = 33;     ///< Lab -> ink table points per axis (9..65)
  std::string description = "textile-print synthetic ink profile";
};

/// Typical solids of common textile inks (reactive/pigment on white cotton): cyan, magenta,
/// yellow, black, red, orange, blue, green, violet. nullopt for other names.
std::optional<InkSolid> typical_ink(std::string_view name);

/// Builds an ICC v4 output profile (PCS Lab) for the inks, in memory.
///
/// Colour model: the inks' optical densities add (Beer-Lambert in the three XYZ bands): an ink at
/// amount t multiplies the paper's X, Y, Z by (solid / paper)^t. The forward table (AToB, the
/// profile's prediction) samples that model; the separation table (BToA) inverts it exactly per
/// node with black plus the two chromatic inks whose hues enclose the colour's hue (full grey
/// component replacement, no complementary inks together), amounts bounded to 0..1. Every intent
/// uses these tables; ink names go into the colorant table.
/// Fails (kColour) on fewer than 1 or more than 15 inks, two chromatic inks of the same hue, an
/// ink lighter than the paper, or a bad grid.
[[nodiscard]] Result<std::vector<std::uint8_t>> build_multi_ink_profile(const MultiInkProfileSpec& spec);

/// build_multi_ink_profile written to `path`. Fails (kIo) naming the file.
[[nodiscard]] Status write_multi_ink_profile(const MultiInkProfileSpec& spec, const std::filesystem::path& path);

}  // namespace tp::rip
