// simulator/fabric/fabric_preset.cpp: measured-style figures for the three fabric presets.
#include "simulator/fabric/fabric_preset.h"

#include <cmath>

namespace tp::sim {

namespace {

// A white that is `level` flat and loses `blue_loss` towards 400 nm (unbleached fibre yellows).
Spectrum white(double level, double blue_loss, double width_nm) {
  Spectrum s{};
  for (int i = 0; i < kBands; ++i) {
    const double t = (band_nm(i) - kFirstBand_nm) / width_nm;
    s[i] = level - blue_loss * std::exp(-t * t);
  }
  return s;
}

}  // namespace

std::optional<FabricPreset> fabric_preset(std::string_view name) {
  // Cotton (pigment inks): matte, yellowish, drinks and spreads ink, strong optical gain.
  if (name == "cotton") return FabricPreset{"cotton", white(0.86, 0.14, 70), 0.035, 0.82, 1.30, 2.6};
  // Polyester satin (disperse dye): bright and smooth, strong colours, little spread.
  if (name == "polyester-satin") return FabricPreset{"polyester-satin", white(0.91, 0.05, 50), 0.020, 1.05, 1.05, 1.7};
  // Silk (acid dye): ivory, fine weave, moderate spread.
  if (name == "silk") return FabricPreset{"silk", white(0.88, 0.16, 90), 0.028, 0.95, 1.15, 2.1};
  return std::nullopt;
}

}  // namespace tp::sim
