// geometry/pattern/import/import_options.h: options shared by every pattern importer.
#pragma once

#include "geometry/pattern/copies.h"
#include "geometry/pattern/curve.h"

namespace tp::geometry {

/// How importers turn a source pattern into physical pieces.
struct PatternImportOptions {
  /// Largest distance (mm) between a curved edge and its flattened polyline.
  double chord_tolerance_mm = kDefaultChordTolerance_mm;
  /// Open cut-on-fold half pieces into whole pieces (unfold_piece); otherwise keep the half with
  /// Piece::fold_edge set.
  bool unfold_cut_on_fold = true;
  /// Expand "cut N" and mirrored pairs into N physical pieces (expand_copies).
  bool expand_quantity = true;
  /// Side the drafted piece of a mirrored pair is for, when the source does not say.
  DraftedSide drafted_side = DraftedSide::kLeft;
  /// Outlines from point sequences (SVG, DXF, OBJ) split into edges where the direction turns by
  /// more than this many degrees.
  double corner_angle_deg = 25;
  /// Reverse clockwise outlines (noted in Pattern::warnings) instead of failing.
  bool fix_orientation = true;
  /// Units of OBJ vertex positions, in mm per unit (1 = mm, 10 = cm, 1000 = m). OBJ texture
  /// coordinates are always mm.
  double obj_position_unit_mm = 1;
  /// Units of a DXF file that does not state them, in mm per unit (AAMA files state them).
  double dxf_default_unit_mm = 1;
};

}  // namespace tp::geometry
