// geometry/samples/skirt8.cpp: the eight-gore skirt with waistband, drafted from measurements.
#include <cmath>
#include <numbers>
#include <string>

#include "geometry/body/dress_form.h"
#include "geometry/samples/internal/draft.h"
#include "geometry/samples/internal/drafts.h"

namespace tp::geometry::samples::internal {
namespace {

constexpr int kGores = 8;
// Ease over the body: a little at the waist (the band sits there), more at the hip.
constexpr double kWaistEaseMm = 35;
constexpr double kHipEaseMm = 90;
// Hem circumference over hip circumference: a gently flared skirt.
constexpr double kHemFlare = 1.45;
constexpr double kWaistbandHeightMm = 35;
// The skirt's hem ends this far above the knee.
constexpr double kAboveKneeMm = 30;

}  // namespace

Result<Pattern> draft_skirt8(const BodyMeasurements& m) {
  const DressFormLandmarks l = dress_form_landmarks(m);
  const double waist = m.waist_mm + kWaistEaseMm, hip = m.hips_mm + kHipEaseMm, hem = hip * kHemFlare;
  const double ww = waist / kGores, wh = hip / kGores, whem = hem / kGores;
  const double dh = m.waist_to_hip_mm, len = m.waist_to_knee_mm - kAboveKneeMm;
  // The band is centred on the waist, so the gores start half its height lower.
  const double top_y = l.waist_y - kWaistbandHeightMm / 2;

  // Gore side seam, waist corner to hem corner on the right: a hip curve, then a straight flare.
  const Vec2 w_r{ww / 2, 0}, h_r{wh / 2, -dh}, e_r{whem / 2, -len};
  const Vec2 flare = normalized(e_r - h_r);
  std::vector<Vec2> seam = cubic_points(w_r, w_r + Vec2{(wh - ww) * 0.35, -dh * 0.3}, h_r - flare * (dh * 0.35), h_r, 24);
  seam.push_back(e_r);
  double seam_len = 0;
  for (size_t i = 1; i < seam.size(); ++i) seam_len += norm(seam[i] - seam[i - 1]);
  // The hem dips at the centre so the centre line is as long as the seams: a level hem.
  const double sag = seam_len - len;

  Pattern p;
  p.name = "skirt8";
  for (int k = 0; k < kGores; ++k) {
    std::vector<Vec2> up(seam.rbegin(), seam.rend()), down;
    for (Vec2 q : seam) down.push_back({-q.x, q.y});
    up.erase(up.begin());
    down.erase(down.begin());
    OutlineBuilder b({-whem / 2, -len});
    b.quad("hem", {0, -len - 2 * sag}, {whem / 2, -len}).polyline("seam_right", up).line("waist", {-ww / 2, 0}).polyline("seam_left", down);
    Piece g;
    g.name = "gore_" + std::to_string(k + 1);
    g.role = "skirt_gore";
    g.source_piece = "gore";
    g.edges = b.edges();
    g.grain = GrainLine{{0, -len + 60}, {0, -60}};
    // Hip notches: seam_right runs hem to waist, seam_left waist to hem.
    const double straight_len = norm(e_r - h_r);
    add_notch(g, "seam_right", straight_len, "hip");
    add_notch(g, "seam_left", seam_len - straight_len, "hip");
    // Gore k is centred at 22.5 + 45 k degrees from the front, towards the wearer's left, so
    // the CF and CB are seams. Its waist sits under the band, tilted out like the cone that
    // runs from the waist to the hem.
    const double theta = (22.5 + 45.0 * k) * std::numbers::pi / 180;
    const double r = waist / (2 * std::numbers::pi);
    const double tilt = std::asin(std::min((hem - waist) / (2 * std::numbers::pi * len), 0.9));
    g.placement = placement_about_y(theta, {r * std::sin(theta), top_y, r * std::cos(theta)});
    const double c = std::cos(tilt), sn = std::sin(tilt), ct = std::cos(theta), st = std::sin(theta);
    // R_y(theta) * R_x(-tilt): the piece's -y (down) leans outwards.
    g.placement->rotation = {ct, -st * sn, st * c, 0, c, sn, -st, -ct * sn, ct * c};
    p.pieces.push_back(std::move(g));
  }

  // Waistband: one strip round the waist, its ends meeting at the CB.
  {
    OutlineBuilder b({0, 0});
    b.line("bottom", {waist, 0}).line("end_right", {waist, kWaistbandHeightMm}).line("top", {0, kWaistbandHeightMm}).line("end_left", {0, 0});
    Piece wb;
    wb.name = "waistband";
    wb.role = "waistband";
    wb.source_piece = "waistband";
    wb.edges = b.edges();
    wb.grain = GrainLine{{40, kWaistbandHeightMm / 2}, {waist - 40, kWaistbandHeightMm / 2}};
    for (int k = 1; k < kGores; ++k) add_notch(wb, "bottom", k * ww, "seam_" + std::to_string(k));
    // Its middle (the CF) faces the front, tangent to the waist; it is rolled into a ring.
    const double r = waist / (2 * std::numbers::pi);
    wb.placement = placement_about_y(0, {-waist / 2, top_y, r});
    p.pieces.push_back(std::move(wb));
  }

  // Gore k's right seam meets gore k+1's left seam; the band's bottom takes the waists from the
  // CB round: gore 5 (index 4) first.
  for (int k = 0; k < kGores; ++k) {
    auto s = add_stitch(p, "gore_" + std::to_string(k + 1), "seam_right", "gore_" + std::to_string((k + 1) % kGores + 1), "seam_left");
    if (!s) return std::unexpected(s.error());
  }
  for (int j = 0; j < kGores; ++j) {
    int gore = (4 + j) % kGores;
    auto s = add_stitch(p, "waistband", "bottom", "gore_" + std::to_string(gore + 1), "waist", j * ww, (j + 1) * ww);
    if (!s) return std::unexpected(s.error());
  }
  if (auto s = add_stitch(p, "waistband", "end_right", "waistband", "end_left"); !s) return std::unexpected(s.error());
  return p;
}

}  // namespace tp::geometry::samples::internal
