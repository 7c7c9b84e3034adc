// geometry/sewing/cloth_material.cpp: the fabric presets and their range checks.
#include "geometry/sewing/cloth_material.h"

#include <cmath>

namespace tp::geometry {
namespace {

// Presets: areal mass from typical data sheets; bending rigidity from Kawabata (KES-FB2) ranges
// (0.01-0.5 gf cm^2/cm, 1 gf cm^2/cm = 9.8 uN m); friction against skin-like surfaces.
const ClothMaterial kPresets[] = {
    {.name = "jersey", .density_g_m2 = 180, .stretch_limit = 0.10, .stretch_stiffness = 0.35,
     .bending_rigidity_uN_m = 2, .friction = 0.5},
    {.name = "cotton-poplin", .density_g_m2 = 120, .stretch_limit = 0.03, .stretch_stiffness = 1.0,
     .bending_rigidity_uN_m = 6, .friction = 0.4},
    {.name = "silk-satin", .density_g_m2 = 80, .stretch_limit = 0.02, .stretch_stiffness = 1.0,
     .bending_rigidity_uN_m = 0.8, .friction = 0.2},
    {.name = "denim", .density_g_m2 = 400, .stretch_limit = 0.02, .stretch_stiffness = 1.0,
     .bending_rigidity_uN_m = 40, .friction = 0.6},
};

}  // namespace

Result<ClothMaterial> cloth_material_preset(const std::string& name) {
  for (const auto& m : kPresets)
    if (m.name == name) return m;
  std::string known;
  for (const auto& m : kPresets) known += (known.empty() ? "" : ", ") + m.name;
  return fail(ErrorCode::kInvalidArgument, "unknown cloth material '" + name + "' (known: " + known + ")");
}

std::vector<std::string> cloth_material_names() {
  std::vector<std::string> out;
  for (const auto& m : kPresets) out.push_back(m.name);
  return out;
}

Status validate_cloth_material(const ClothMaterial& m) {
  auto bad = [&](const std::string& field, const std::string& range) {
    return fail(ErrorCode::kInvalidArgument, "cloth material '" + m.name + "': " + field + " must be " + range);
  };
  if (!(m.density_g_m2 > 0 && m.density_g_m2 <= 2000)) return bad("density_g_m2", "in (0, 2000]");
  if (!(m.stretch_limit > 0 && m.stretch_limit <= 0.5)) return bad("stretch_limit", "in (0, 0.5]");
  if (!(m.stretch_stiffness > 0 && m.stretch_stiffness <= 1)) return bad("stretch_stiffness", "in (0, 1]");
  if (!(m.bending_rigidity_uN_m >= 0 && m.bending_rigidity_uN_m <= 10000)) return bad("bending_rigidity_uN_m", "in [0, 10000]");
  if (!(m.friction >= 0 && m.friction <= 2)) return bad("friction", "in [0, 2]");
  return {};
}

}  // namespace tp::geometry
