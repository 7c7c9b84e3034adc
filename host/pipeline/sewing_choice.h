// host/pipeline/sewing_choice.h: the sewing solver that garment.sewing "auto" picks for a pattern,
// shared by the garment stage and `printctl bench garment`.
#pragma once

#include "geometry/pattern/pattern.h"
#include "geometry/sewing/sew_garment.h"

namespace tp::host {

struct SewingChoice {
  geometry::SewSolver solver = geometry::SewSolver::kArap;
  bool one_level = false;  ///< sew on one level (no coarse mesh first)
};

/// Whether a piece of the pattern comes without a 3D placement (it is placed by its role).
[[nodiscard]] bool placed_by_role(const geometry::Pattern& pattern);

/// What "auto" sews `pattern` with: XPBD on one level when a piece comes without a 3D placement
/// (FreeSewing, DXF, native without one: the coarse level's shape, carried to the fine mesh, left
/// bella 42's bodice hem 48 vertices inside the form, one level none), XPBD (its default levels)
/// for a GarmentCode pattern, ARAP otherwise (the samples and native patterns placed for the
/// dress form: XPBD leaves the sample dress's side seams open). docs/garments.md has the figures.
[[nodiscard]] SewingChoice auto_sewing(const geometry::Pattern& pattern, bool garmentcode);

}  // namespace tp::host
