// host/pipeline/sewing_choice.cpp: garment.sewing "auto", by how the pattern's pieces are placed.
#include "host/pipeline/sewing_choice.h"

namespace tp::host {

bool placed_by_role(const geometry::Pattern& pattern) {
  for (const geometry::Piece& p : pattern.pieces)
    if (!p.placement) return true;
  return false;
}

SewingChoice auto_sewing(const geometry::Pattern& pattern, bool garmentcode) {
  if (placed_by_role(pattern) || garmentcode) return {geometry::SewSolver::kXpbd};
  return {geometry::SewSolver::kArap};
}

}  // namespace tp::host
