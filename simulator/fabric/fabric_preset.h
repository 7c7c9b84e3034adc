// simulator/fabric/fabric_preset.h: the fabrics the colorimetric printer knows (cotton,
// polyester satin, silk): their white, surface reflection, ink uptake, drop spread and the
// Yule-Nielsen n their weave gives.
#pragma once

#include <optional>
#include <string_view>

#include "device/colour/colorimetry.h"

namespace tp::sim {

// The colour science lives in device/colour (shared with the host's proof checks).
using device::band_nm;
using device::delta_e_2000;
using device::kBands;
using device::kD50White;
using device::kFirstBand_nm;
using device::Lab;
using device::lab_to_xyz;
using device::Spectrum;
using device::spectrum_to_xyz;
using device::Xyz;
using device::xyz_to_lab;
using device::xyz_to_srgb8;

struct FabricPreset {
  std::string_view name;
  Spectrum white{};                 ///< body reflectance of the bare fabric per band
  double surface_reflectance = 0;   ///< light the fibre surface returns before ink can absorb it
  double ink_uptake = 1;            ///< optical density the fabric lets an ink reach (1 = nominal)
  double drop_spread = 1;           ///< how much further than on film a drop wicks (area factor)
  double yule_nielsen_n = 2;        ///< optical dot gain of the weave
};

/// The preset called `name`, or nothing if there is none.
std::optional<FabricPreset> fabric_preset(std::string_view name);

}  // namespace tp::sim
