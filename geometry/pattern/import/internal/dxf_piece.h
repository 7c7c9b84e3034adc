// geometry/pattern/import/internal/dxf_piece.h: one DXF-AAMA block to a drafted piece.
#pragma once

#include <string>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/import/internal/dxf_groups.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::internal {

/// A drafted piece from one block with what its annotation says about cutting it.
struct DxfPiece {
  Piece piece;
  int quantity = 1;
  bool mirror_pairs = false;
  std::string size;
};

/// Builds the piece of `block` (`unit_mm` mm per drawing unit). A block without a boundary or
/// sew line gives a piece with no edges. Fails (kInvalidPattern) when the outline does not close.
[[nodiscard]] Result<DxfPiece> build_dxf_piece(const DxfBlock& block, double unit_mm, const std::string& file,
                                               const PatternImportOptions& options, std::vector<std::string>& warnings);

}  // namespace tp::geometry::internal
