// geometry/pattern/import/internal/svg_part.h: what the FreeSewing reader collects per part before building a piece.
#pragma once

#include <string>
#include <vector>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::internal {

/// A <path> inside a part: its attributes and the map from its coordinates to the part's.
struct SvgPathElement {
  std::string id, cls, d, data_text, marker_start;
  Affine2 to_part;
  int line = 0;
};

/// A <use> of a notch symbol: its position in part coordinates.
struct SvgNotchMark {
  Vec2 at;
  bool double_notch = false;
  int line = 0;
};

/// One FreeSewing part group.
struct SvgPart {
  std::string group_id;
  std::string name;  ///< "back" from "penelope.back"
  int line = 0;
  std::vector<SvgPathElement> paths;
  std::vector<SvgNotchMark> notches;
  std::vector<std::string> texts;  ///< each <text> element's content
};

/// Drafted piece of a part plus how many to cut.
struct SvgPiece {
  Piece piece;
  int quantity = 1;
  bool mirror_pairs = false;
};

/// Builds the piece of one part (y flipped to up, edges, notches, grain, fold, darts, quantity).
/// Returns a piece with no edges when the part has no closed seam line. Warnings go to `warnings`.
[[nodiscard]] Result<SvgPiece> build_svg_piece(const SvgPart& part, const std::string& file, const PatternImportOptions& options,
                                               std::vector<std::string>& warnings);

}  // namespace tp::geometry::internal
