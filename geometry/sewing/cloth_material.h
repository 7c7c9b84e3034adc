// geometry/sewing/cloth_material.h: fabric properties the drape solver uses, and the named presets.
#pragma once

#include <string>
#include <vector>

#include "geometry/common/error.h"

namespace tp::geometry {

/// A fabric for the cloth solver. Units are physical so presets can be compared with data sheets.
struct ClothMaterial {
  std::string name = "cotton-poplin";
  double density_g_m2 = 120;         ///< areal mass
  /// Strain limit: no triangle's principal stretch leaves [1 - limit, 1 + limit] (0.03 = 3 %).
  double stretch_limit = 0.03;
  /// In-plane stiffness inside the limit, as the fraction of the way to the rest shape each
  /// triangle is moved per substep (0 < s <= 1; 1: as stiff as the solver allows).
  double stretch_stiffness = 1.0;
  double bending_rigidity_uN_m = 6;  ///< bending rigidity B (micro-newton metres; Kawabata B)
  double friction = 0.4;             ///< Coulomb friction coefficient against the body
};

/// The preset called `name`: "jersey", "cotton-poplin", "silk-satin" or "denim". Fails with
/// kInvalidArgument naming the unknown preset and the known ones.
[[nodiscard]] Result<ClothMaterial> cloth_material_preset(const std::string& name);

/// Names of the presets, in the order above.
std::vector<std::string> cloth_material_names();

/// Checks a material's ranges; kInvalidArgument naming the field otherwise.
[[nodiscard]] Status validate_cloth_material(const ClothMaterial& m);

}  // namespace tp::geometry
