// geometry/cutfile/cut_job.h: the cut contours of a job's pieces (cut line, notches, grain line,
// drill holes, sew line, internal lines, annotation), in piece mm and placed as on the roll.
#pragma once

#include <string>
#include <vector>

#include "geometry/allowance/finishing.h"
#include "geometry/common/error.h"
#include <array>
#include "geometry/nesting/marker.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Everything the cutter needs of one placed piece. Geometry is in piece mm (the block of a
/// DXF-AAMA file); `piece_to_roll` places it on the roll.
struct PieceCut {
  std::string name;                                ///< unique in the job (copies get "#2", ...)
  int piece = 0;                                   ///< index into Pattern::pieces
  Affine2 piece_to_roll;
  bool mirrored = false;
  Polygon cut_line;                                ///< the printed outline, counter-clockwise in piece mm
  Polygon cut_line_notched;                        ///< ASTM layer 1: the cut line with V and U notches cut in
  Polygon sew_line;                                ///< layer 14
  /// Layer 4: one slit line per notch, from where it opens on the cut line to its depth.
  std::vector<std::array<Vec2, 2>> notch_lines;
  std::vector<NotchType> notch_types;
  std::vector<std::vector<Vec2>> notch_shapes;     ///< every notch's full cut (slit, V, T, U), for drawings
  std::vector<std::array<Vec2, 2>> grain;          ///< layer 7 (one line, or none)
  std::vector<DrillHole> drill_holes;              ///< layer 13
  std::vector<std::vector<Vec2>> internal_lines;   ///< layer 8
  std::vector<std::vector<Vec2>> mark_strokes;     ///< layer 15 strokes: label and grain arrow (marker-layer mode)
  std::vector<std::string> annotation;             ///< "Piece Name: front", "Size: M", "Quantity: 1", ...
};

/// Which cut-file axis runs along the roll (a cutter setting; docs/roll-frame.md). Both keep the
/// printed face up, so the pieces read as printed.
enum class CutterRollAxis {
  kX,  ///< DXF X = roll y (from the leading edge), DXF Y = roll x (from the left selvedge)
  kY,  ///< DXF X = roll x, DXF Y = marker length - roll y (origin at the trailing edge's left corner)
};

/// A job's cut contours on one marker.
struct CutJob {
  std::string job_name;
  std::string pattern_name;
  std::string size;                ///< the pattern's size ("M"), empty if none
  double fabric_width_mm = 0;
  double marker_length_mm = 0;
  CutterRollAxis roll_axis = CutterRollAxis::kX;
  std::vector<PieceCut> pieces;  ///< in marker placement order
};

/// The roll frame (mm, y down the roll, seen from the printed face) to the cutting table's frame
/// of `job.roll_axis` (mm, y up, seen from above the printed face).
[[nodiscard]] Affine2 roll_to_cutter(const CutJob& job);

/// Assembles the cut contours of every placement of `marker`: cut line from the resolved
/// allowance (the outline the renderer prints), notches cut into it, grain, drill holes, sew line,
/// internal lines, and the label/grain strokes when finishing.marks is kMarkerLayer.
/// Fails naming the placement or piece when the marker refers to a missing piece or an
/// outline cannot be built.
[[nodiscard]] Result<CutJob> make_cut_job(const Pattern& pattern, const Finishing& finishing, const Marker& marker);

/// Maps a point list through an affine map.
std::vector<Vec2> transformed(const std::vector<Vec2>& pts, const Affine2& m);

}  // namespace tp::geometry
