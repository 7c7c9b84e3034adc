// geometry/samples/internal/bodice.h: the bodice block (front and back halves) the tops and the dress are drafted from.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "geometry/body/measurements.h"
#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::samples::internal {

/// Ease and length of a bodice. Lengths in mm; hem_y_mm < 0 is below the waist.
struct BodiceOptions {
  double bust_ease_mm = 60;
  double waist_ease_mm = 60;
  double hip_ease_mm = 70;
  double hem_y_mm = 0;           ///< 0: ends at the waist
  double side_flare_mm = 0;      ///< extra width per side seam at the hem (below the hip)
};

/// Key points of one half (front or back) in the draft frame: waist at y = 0, centre (CF or
/// CB) at x = 0, side seam at +x; the right side of the fabric faces the viewer.
struct HalfBlock {
  Vec2 centre_neck, neck_point, shoulder_tip, underarm, waist_side, hip_side, hem_side;
  double hem_y = 0, hip_y = 0;
  Vec2 apex;               ///< bust point (front) or shoulder-blade point (back)
  double waist_intake = 0; ///< waist dart width (princess intake at the waist)
  double shoulder_intake = 0;
  std::vector<Vec2> armhole;   ///< underarm to shoulder tip
  std::vector<Vec2> neckline;  ///< neck point to centre neck
};

/// The block: front half with its bust dart opening on the side seam, back half.
struct BodiceBlock {
  HalfBlock front, back;
  double bust_dart_mm = 0;        ///< bust dart mouth on the front side seam
  double bust_dart_centre_mm = 0; ///< arc length from the side seam's waist end to the dart's centre
  double side_length_mm = 0;      ///< back side seam, underarm to waist
};

/// Drafts the block for `m` (straight shoulder lines, Bezier armholes and necklines).
BodiceBlock bodice_block(const BodyMeasurements& m, const BodiceOptions& options);

/// Side seam below the waist (waist to hem), the same on front and back.
std::vector<Vec2> lower_side(const HalfBlock& h);

/// The simple top's left front (bust dart at the side, waist dart) and right back (shoulder
/// and waist darts), waist length.
std::pair<Piece, Piece> simple_top_halves(const BodiceBlock& b);

/// Princess panels of one side: {centre front half, side front, centre back, side back}. The
/// side front's bust dart is pivoted into the princess seam at the shoulder.
std::vector<Piece> princess_panels(const BodiceBlock& b);

/// A set-in sleeve whose cap is exactly `back_armhole_mm` + `front_armhole_mm` long (cap height
/// found by bisection), `underarm_mm` long below the cap and `hem_width_mm` wide at the hem.
/// Its bicep is the upper arm plus 70 mm of ease, and at least 0.765 of the armhole (so a
/// small size's cap keeps size M's height for its width and sews without crumpling).
/// The crown notch splits the cap at the back armhole's length.
Piece draft_sleeve(const BodyMeasurements& m, double back_armhole_mm, double front_armhole_mm, double underarm_mm,
                   double hem_width_mm);

/// Sews chain A (edges of possibly several pieces, running from point P to point Q) to chain B
/// (running from Q back to P), splitting stitches wherever either chain changes edge. Fails with
/// kInvalidPattern when the chains' lengths differ by more than 0.1 %, naming both lengths.
[[nodiscard]] Status sew_chains(Pattern& p, const std::vector<std::pair<std::string, std::string>>& chain_a,
                                const std::vector<std::pair<std::string, std::string>>& chain_b,
                                const std::string& seam_name);

/// Placements of the draft frame around the dress form: the front half's plane at +r, the
/// back's (turned round) at -r, waist at `waist_y_mm`.
Placement3d front_placement(double r_mm, double waist_y_mm);
Placement3d back_placement(double r_mm, double waist_y_mm);

}  // namespace tp::geometry::samples::internal
