// geometry/garment/flat_pieces.h: pieces no stitch joins to the rest (a pocket bag, a label), printed flat beside a 3D
// garment.
#pragma once

#include <vector>

#include "geometry/common/error.h"
#include "geometry/garment/garment.h"
#include "geometry/mesh/mesh_pattern.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Indices of the pieces that no stitch joins to another piece (a piece's own darts do not
/// count), ascending; none when the pattern has no stitches at all (a flat job). The fit checks
/// leave the same pieces out (fit_checks.h).
[[nodiscard]] std::vector<int> unjoined_pieces(const Pattern& pattern);

/// A pattern and its meshes without some pieces: stitches renumbered, those touching a dropped
/// piece left out.
struct PatternPart {
  Pattern pattern;
  PatternMesh meshes;
  std::vector<int> pieces;    ///< per piece of the part, its index in the whole pattern
  std::vector<int> stitches;  ///< per stitch of the part, its index in the whole pattern
};
/// `pattern` and `meshes` without the pieces in `drop` (ascending indices).
[[nodiscard]] PatternPart pattern_without(const Pattern& pattern, const PatternMesh& meshes,
                                          const std::vector<int>& drop);

/// The whole pattern's garment: the part's pieces where `part_garment` (a garment of part.pattern)
/// has them, the pieces the part left out where flat_garment (the layout of a job without a
/// body) puts them, so their print is the one a flat job gives them. Fails when the meshes do
/// not match.
[[nodiscard]] Result<Garment> garment_with_flat_pieces(const Pattern& pattern, const PatternMesh& meshes,
                                                       const PatternPart& part, const Garment& part_garment);

/// `garment` with the charts of `pieces` (ascending) replaced by those of `source` (a garment
/// of the same pattern), their vertices appended: the flat pieces put back into a draped
/// garment. Pieces out of range of either are skipped.
[[nodiscard]] Garment with_pieces_from(const Garment& garment, const Garment& source, const std::vector<int>& pieces);

/// `garment` with the charts of the pieces in `drop` emptied (no vertices, no triangles; the
/// piece order kept) and the 3D vertices only they used removed: the 3D garment as worn, for
/// OBJ files, previews and the drape.
[[nodiscard]] Garment garment_without(const Garment& garment, const std::vector<int>& drop);

}  // namespace tp::geometry
