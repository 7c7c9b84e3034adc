// host/pipeline/sewing_choice.h: the sewing solver that garment.sewing "auto" picks for a pattern,
// shared by the garment stage and `printctl bench garment`.
#pragma once

#include "geometry/pattern/pattern.h"
#include "geometry/sewing/sew_garment.h"

namespace tp::host {

struct SewingChoice {
  geometry::SewSolver solver = geometry::SewSolver::kArap;
};

/// Whether a piece of the pattern comes without a 3D placement (it is placed by its role).
[[nodiscard]] bool placed_by_role(const geometry::Pattern& pattern);

/// What "auto" sews `pattern` with: XPBD (its default levels) when a piece comes without a 3D
/// placement (FreeSewing, DXF, native without one) or for a GarmentCode pattern, ARAP otherwise
/// (the samples and native patterns placed for the dress form). docs/garments.md has the figures.
[[nodiscard]] SewingChoice auto_sewing(const geometry::Pattern& pattern, bool garmentcode);

}  // namespace tp::host
