// geometry/pattern/suggest_stitches.h: proposing stitches for patterns that come without them (FreeSewing, DXF).
#pragma once

#include <string>
#include <vector>

#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// How candidates are found and scored.
struct SuggestOptions {
  /// Whole edges are candidates when their lengths differ by at most this fraction of the longer.
  double length_tolerance_ratio = 0.05;
  /// An edge sewn to two edges in turn (a sleeve cap to the front and back armholes) may be this
  /// fraction longer or shorter than their sum (ease).
  double max_ease_ratio = 0.06;
  /// Suggestions scoring below this (0..1) are not returned.
  double min_score = 0.7;
  /// Notches match when within this distance (mm) of each other once the seam is laid together.
  double notch_match_mm = 5;
  /// Skip two-edge (split) candidates when the pattern has more edges than this (cost is cubic).
  int max_edges_for_splits = 400;
};

/// One proposed seam: one stitch, or two for an edge sewn to two edges in turn; a dart is one.
struct StitchSuggestion {
  std::vector<Stitch> stitches;
  double score = 0;       ///< 0..1; higher is surer
  std::string reason;     ///< what matched, for the operator ("dart", "lengths 231.6/230.2 mm, ...")
};

/// A consistent set of suggested stitches (each edge used once) for the edges no stitch uses yet,
/// best first. Darts (Piece::darts) are always suggested (score 1). Other candidates are pairs of
/// edges, right sides together (a's start meets b's end), scored on: equal length; equal rise
/// along the grain read in opposite directions (pieces hang grain-vertical, so seam ends meet at
/// the same height: this tells a front's left side seam from its right); notch groups (a double
/// notch is the back) falling at the same places; one end's corners adding up to a straight line
/// (drafting squares corners so hems and necklines run on); matching edge names. One edge may
/// also be sewn to two edges in turn (a sleeve cap to the front and back armholes, with ease up
/// to max_ease_ratio), scored on length, rise and notches. Sleeves close on themselves; other
/// pieces, and mirror copies along the same edge (centre seams aside), yield to alternatives.
/// Two hems are never sewn together, nor an unfolded piece's edge to its own mirror image. Seams
/// with no evidence beyond length (level edges without notches) stay under the default minimum.
/// Greedy by score, so a job may accept the list as is, drop entries or add its own stitches.
/// Then bands (role waistband, collar, cuff): a band's free edge is sewn along a run of three or
/// more free edges the chosen seams join end to end (a skirt's waist across its darts and side
/// seams), within max_ease_ratio of its length; a whole loop starts at a centre seam.
std::vector<StitchSuggestion> suggest_stitches(const Pattern& pattern, const SuggestOptions& options = {});

/// Appends the stitches of the suggestions scoring at least `min_score` to pattern.stitches;
/// returns how many stitches were added.
int accept_suggestions(Pattern& pattern, const std::vector<StitchSuggestion>& suggestions, double min_score = 0);

}  // namespace tp::geometry
