// geometry/samples/princess_garments.cpp: the princess-seamed blouse (9 pieces) and dress (10 pieces).
#include <cmath>
#include <numbers>

#include "geometry/body/dress_form.h"
#include "geometry/samples/internal/bodice.h"
#include "geometry/samples/internal/draft.h"
#include "geometry/samples/internal/drafts.h"

namespace tp::geometry::samples::internal {
namespace {

using Chain = std::vector<std::pair<std::string, std::string>>;

// The whole centre front of the blouse: the drafted left half and its mirror image joined at
// the CF (cut on the fold, unfolded).
Piece whole_centre_front(const Piece& left) {
  Piece right = mirror_piece(left, "front_r");
  // left: hem, princess, shoulder, neckline, cf. right (mirrored): cf, neckline, shoulder, princess, hem.
  const auto edge = [](const Piece& p, const char* n) { return p.edges[find_edge(p, n)]; };
  Edge hem{"hem", EdgeCurve::kPolyline, {}, edge(right, "hem").points_mm};
  for (size_t i = 1; i < edge(left, "hem").points_mm.size(); ++i) hem.points_mm.push_back(edge(left, "hem").points_mm[i]);
  Edge neck{"neckline", EdgeCurve::kPolyline, {}, edge(left, "neckline").points_mm};
  for (size_t i = 1; i < edge(right, "neckline").points_mm.size(); ++i) neck.points_mm.push_back(edge(right, "neckline").points_mm[i]);
  Edge pl = edge(left, "princess"), sl = edge(left, "shoulder"), sr = edge(right, "shoulder"), pr = edge(right, "princess");
  pl.name = "princess_l", sl.name = "shoulder_l", sr.name = "shoulder_r", pr.name = "princess_r";
  Piece whole = left;
  whole.name = "centre_front";
  whole.source_piece = "centre_front";
  whole.edges = {hem, pl, sl, neck, sr, pr};
  whole.fold_edge.reset();
  whole.grain = GrainLine{{0, hem.points_mm.front().y + 40}, {0, neck.points_mm[neck.points_mm.size() / 2].y - 40}};
  return whole;
}

struct PrincessSpec {
  const char* name;
  BodiceOptions bodice;
  bool centre_front_seam;   // dress: front in two halves; blouse: one front piece
  double sleeve_underarm_mm;
  double sleeve_hem_ease_mm;
};

Result<Pattern> draft_princess(const BodyMeasurements& m, const PrincessSpec& spec) {
  BodiceBlock block = bodice_block(m, spec.bodice);
  std::vector<Piece> panels = princess_panels(block);  // front_l, side_front_l, back_r, side_back_r
  const DressFormLandmarks l = dress_form_landmarks(m);
  const double r = (m.bust_mm + spec.bodice.bust_ease_mm) / (2 * std::numbers::pi);
  for (Piece& pc : panels) pc.placement = pc.role.find("back") != std::string::npos ? back_placement(r, l.waist_y) : front_placement(r, l.waist_y);

  Pattern p;
  p.name = spec.name;
  const Piece& front_l = panels[0];
  const std::string front_l_name = spec.centre_front_seam ? "front_l" : "centre_front";
  const std::string front_r_name = spec.centre_front_seam ? "front_r" : "centre_front";
  if (spec.centre_front_seam) {
    p.pieces.push_back(front_l);
    p.pieces.push_back(mirror_piece(front_l, "front_r"));
  } else {
    p.pieces.push_back(whole_centre_front(front_l));
  }
  p.pieces.push_back(panels[1]);
  p.pieces.push_back(mirror_piece(panels[1], "side_front_r"));
  p.pieces.push_back(panels[2]);
  p.pieces.push_back(mirror_piece(panels[2], "back_l"));
  p.pieces.push_back(panels[3]);
  p.pieces.push_back(mirror_piece(panels[3], "side_back_l"));

  // Sleeves: the cap matches the armhole (side back + side front) exactly.
  const double back_arm = edge_length_mm(panels[3].edges[find_edge(panels[3], "armhole")]);
  const double front_arm = edge_length_mm(panels[1].edges[find_edge(panels[1], "armhole")]);
  Piece sleeve = draft_sleeve(m, back_arm, front_arm, spec.sleeve_underarm_mm, m.upper_arm_mm + spec.sleeve_hem_ease_mm);
  {
    // On the left arm: its length along the arm, its face outwards, the crown over the joint.
    const double a = m.arm_angle_deg * std::numbers::pi / 180, ca = std::cos(a), sa = std::sin(a);
    Box2 bb = bounds(outline(sleeve));
    const double crown_y = bb.max.y, tube_r = bb.width() / (2 * std::numbers::pi);
    Vec3 n{ca, sa, 0}, up{-sa, ca, 0};
    Vec3 crown = l.arm_joint_left + up * (0.5 * l.upper_arm_radius_mm) + n * tube_r;
    sleeve.placement = Placement3d{{0, -sa, ca, 0, ca, sa, -1, 0, 0}, crown - up * crown_y};
  }
  p.pieces.push_back(sleeve);
  p.pieces.push_back(mirror_piece(sleeve, "sleeve_r"));

  const std::string fl_pr = spec.centre_front_seam ? "princess" : "princess_l";
  const std::string fr_pr = spec.centre_front_seam ? "princess" : "princess_r";
  const std::string fl_sh = spec.centre_front_seam ? "shoulder" : "shoulder_l";
  const std::string fr_sh = spec.centre_front_seam ? "shoulder" : "shoulder_r";
  struct Seam { const char* name; Chain a, b; };
  std::vector<Seam> seams{
      {"left front princess", {{front_l_name, fl_pr}}, {{"side_front_l", "princess"}}},
      {"right front princess", {{front_r_name, fr_pr}}, {{"side_front_r", "princess"}}},
      {"left back princess", {{"back_l", "princess"}}, {{"side_back_l", "princess"}}},
      {"right back princess", {{"back_r", "princess"}}, {{"side_back_r", "princess"}}},
      {"centre back", {{"back_r", "cb"}}, {{"back_l", "cb"}}},
      {"left shoulder", {{"side_front_l", "shoulder"}, {front_l_name, fl_sh}}, {{"back_l", "shoulder"}, {"side_back_l", "shoulder"}}},
      {"right shoulder", {{front_r_name, fr_sh}, {"side_front_r", "shoulder"}}, {{"side_back_r", "shoulder"}, {"back_r", "shoulder"}}},
      {"left side", {{"side_front_l", "side"}}, {{"side_back_l", "side"}}},
      {"right side", {{"side_front_r", "side"}}, {{"side_back_r", "side"}}},
      {"left armhole", {{"sleeve_l", "cap"}}, {{"side_front_l", "armhole"}, {"side_back_l", "armhole"}}},
      {"right armhole", {{"sleeve_r", "cap"}}, {{"side_back_r", "armhole"}, {"side_front_r", "armhole"}}},
      {"left sleeve seam", {{"sleeve_l", "underarm_right"}}, {{"sleeve_l", "underarm_left"}}},
      {"right sleeve seam", {{"sleeve_r", "underarm_left"}}, {{"sleeve_r", "underarm_right"}}},
  };
  if (spec.centre_front_seam) seams.push_back({"centre front", {{"front_l", "cf"}}, {{"front_r", "cf"}}});
  for (const Seam& s : seams)
    if (auto st = sew_chains(p, s.a, s.b, s.name); !st) return std::unexpected(st.error().with_context(spec.name));
  return p;
}

}  // namespace

Result<Pattern> draft_blouse(const BodyMeasurements& m) {
  PrincessSpec spec{"blouse", {}, false, 0.42 * m.arm_length_mm - 90, 40};
  spec.bodice.hem_y_mm = -0.8 * m.waist_to_hip_mm;
  return draft_princess(m, spec);
}

Result<Pattern> draft_dress(const BodyMeasurements& m) {
  PrincessSpec spec{"dress", {}, true, 110, 60};
  spec.bodice.hem_y_mm = -(m.waist_to_knee_mm - 40);
  spec.bodice.side_flare_mm = 60;
  return draft_princess(m, spec);
}

}  // namespace tp::geometry::samples::internal
