// geometry/allowance/finishing.h: what a job asks of finishing: seam and hem allowances, corner
// shapes, notches, and where piece labels and grain lines go.
#pragma once

#include <string>
#include <vector>

#include "geometry/common/image.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// How the allowance is cut where two edges meet at a convex corner (concave corners are always
/// the intersection of the two offset lines).
enum class CornerStyle {
  kMitre,            ///< the two offset lines meet (bevelled beyond `Finishing::mitre_limit`)
  kSquare,           ///< each allowance runs straight past the corner and ends square to its seam
  kReflectIncoming,  ///< the incoming edge's allowance ends in the mirror of the outgoing cut line
                     ///< (folded along its seam line it lies along the next edge's cut line: hems)
  kReflectOutgoing,  ///< the same for the outgoing edge
};

/// Where printed marks (piece label, grain arrow) go.
enum class MarkMode {
  kNone,         ///< nothing printed, nothing in the cut file's annotation layer
  kPrinted,      ///< printed small and neutral in the seam allowance, where the sewn garment hides them
  kMarkerLayer,  ///< not printed; written to the cut files' annotation layer (pen or marker plot)
};

/// Allowance width for one edge, overriding the defaults.
struct EdgeAllowance {
  std::string piece;
  std::string edge;
  double width_mm = 10;
};

/// Corner style at the end of one edge (the corner it shares with the next edge).
struct CornerOverride {
  std::string piece;
  std::string edge;
  CornerStyle style = CornerStyle::kMitre;
};

/// Finishing settings of a job. Widths in mm.
struct Finishing {
  double seam_allowance_mm = 10;   ///< edges sewn to another edge
  double hem_allowance_mm = 25;    ///< hems: edges whose name contains "hem", and `hem_edges`
  double edge_allowance_mm = 10;   ///< other unsewn edges (neckline, armhole facings, openings)
  std::vector<EdgeAllowance> edge_widths;     ///< per-edge overrides
  std::vector<EdgeAllowance> hem_edges;       ///< extra hems (width_mm ignored: hem_allowance_mm)
  CornerStyle seam_corner = CornerStyle::kMitre;  ///< corner style where no hem is involved
  bool reflect_hem_corners = true;  ///< hem corners mirror the neighbouring cut line (else seam_corner)
  std::vector<CornerOverride> corners;
  double mitre_limit = 3;           ///< a mitre longer than this many allowance widths is bevelled

  /// Whether the allowance carries the print (category 1 across seams, 2 mirrored at edges);
  /// false leaves it unprinted (marks are still printed).
  bool textured_allowance = true;

  bool notch_stitch_ends = true;    ///< notch both ends of every stitched span
  NotchType stitch_notch_type = NotchType::kSlit;
  double notch_depth_mm = 4;        ///< into the allowance, at most 60 % of its width
  double notch_width_mm = 3;        ///< V, T and U notches

  MarkMode marks = MarkMode::kPrinted;
  std::string job_name;             ///< printed in the label, with the piece name and pattern size
  double label_height_mm = 4;       ///< capital height of label text
  Rgba8 mark_colour{150, 150, 150, 255};
};

}  // namespace tp::geometry
