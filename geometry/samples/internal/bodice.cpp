// geometry/samples/internal/bodice.cpp: bodice block drafting, princess panels, set-in sleeve, seam chains.
#include "geometry/samples/internal/bodice.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/samples/internal/draft.h"

namespace tp::geometry::samples::internal {
namespace {

// The garment's underarm sits this far below the body's armpit.
constexpr double kUnderarmDropMm = 25;
// Dart points stop short of the bust point by this much.
constexpr double kDartShortOfApexMm = 25;
// The bust dart's upper leg meets the side seam this far below the underarm.
constexpr double kBustDartBelowUnderarmMm = 55;
// Radius of the rounding of princess seams at the bust and shoulder-blade points.
constexpr double kPrincessFilletMm = 30;
// Chains sewn together may differ by this fraction of their length.
constexpr double kChainLengthTol = 1e-3;
// Smallest sleeve bicep per mm of armhole: size M's (350 mm on a 457 mm armhole) rounded down,
// so M and L keep the bicep of their ease and S gets the proportions of M.
constexpr double kBicepPerArmhole = 0.765;

std::vector<Vec2> quad_points(Vec2 a, Vec2 c, Vec2 b, int n) {
  std::vector<Vec2> out;
  for (int i = 0; i <= n; ++i) {
    double t = static_cast<double>(i) / n, u = 1 - t;
    out.push_back(a * (u * u) + c * (2 * u * t) + b * (t * t));
  }
  return out;
}

double length(const std::vector<Vec2>& pts) {
  double l = 0;
  for (size_t i = 1; i < pts.size(); ++i) l += norm(pts[i] - pts[i - 1]);
  return l;
}

// Points of a polyline with the corner at `corner` rounded by a quadratic over `r` mm each side.
std::vector<Vec2> rounded(const std::vector<Vec2>& pts, size_t corner, double r) {
  if (corner == 0 || corner + 1 >= pts.size()) return pts;
  Vec2 c = pts[corner];
  double rin = std::min(r, 0.45 * norm(c - pts[corner - 1])), rout = std::min(r, 0.45 * norm(pts[corner + 1] - c));
  Vec2 a = c + normalized(pts[corner - 1] - c) * rin, b = c + normalized(pts[corner + 1] - c) * rout;
  std::vector<Vec2> out(pts.begin(), pts.begin() + static_cast<long>(corner));
  std::vector<Vec2> q = quad_points(a, c, b, 12);
  out.insert(out.end(), q.begin(), q.end());
  out.insert(out.end(), pts.begin() + static_cast<long>(corner) + 1, pts.end());
  return out;
}

// Rounds the corner like `rounded`, with the radius chosen (bisection) so that the polyline gets
// shorter by `loss_mm`: the two sides of a princess seam lose the same length to their rounding.
std::vector<Vec2> rounded_with_loss(const std::vector<Vec2>& pts, size_t corner, double loss_mm) {
  const double full = length(pts);
  double lo = 0, hi = 4 * kPrincessFilletMm;
  for (int i = 0; i < 50; ++i) {
    double mid = (lo + hi) / 2;
    (full - length(rounded(pts, corner, mid)) < loss_mm ? lo : hi) = mid;
  }
  return rounded(pts, corner, (lo + hi) / 2);
}

Vec2 rotate_about(Vec2 p, Vec2 centre, double angle) {
  double c = std::cos(angle), s = std::sin(angle);
  Vec2 d = p - centre;
  return centre + Vec2{c * d.x - s * d.y, s * d.x + c * d.y};
}

// Foot of the perpendicular from p onto the line a-b.
Vec2 project(Vec2 p, Vec2 a, Vec2 b) {
  Vec2 d = normalized(b - a);
  return a + d * dot(p - a, d);
}

// Princess seam points from the hem up to the apex, on one side of the axis x = apex.x:
// `sign` -1 for the centre panel's edge, +1 for the side panel's. Intake halves are taken off.
std::vector<Vec2> princess_lower(const HalfBlock& h, double hem_intake, double sign) {
  std::vector<Vec2> pts;
  const double x = h.apex.x;
  if (h.hem_y < 0) {
    pts.push_back({x + sign * hem_intake / 2, h.hem_y});
    if (h.hem_y < h.hip_y) pts.push_back({x, h.hip_y});
  }
  pts.push_back({x + sign * h.waist_intake / 2, 0});
  pts.push_back(h.apex);
  return pts;
}

Piece make_piece(const std::string& name, const std::string& role, const std::vector<Edge>& edges, Vec2 grain_from,
                 Vec2 grain_to) {
  Piece p;
  p.name = name;
  p.role = role;
  p.source_piece = name.substr(0, name.size() > 2 && name[name.size() - 2] == '_' ? name.size() - 2 : name.size());
  p.edges = edges;
  p.grain = GrainLine{grain_from, grain_to};
  return p;
}

}  // namespace

BodiceBlock bodice_block(const BodyMeasurements& m, const BodiceOptions& o) {
  BodiceBlock b;
  const double nr = m.neck_mm / (2 * std::numbers::pi), nw = nr + 12;
  const double bl = m.back_length_mm, hps_y = bl + 18;
  const double slope = m.shoulder_slope_deg * std::numbers::pi / 180, slope_f = slope + 2 * std::numbers::pi / 180;
  const double tip_x = m.shoulder_width_mm / 2 + 5;
  const double shoulder_len = (tip_x - nw) / std::cos(slope);
  const double quarter = (m.bust_mm + o.bust_ease_mm) / 4;
  const double waist_q = (m.waist_mm + o.waist_ease_mm) / 4;

  // Back: neck, shoulder lengthened by the shoulder dart, armhole, straight side seam.
  HalfBlock& bk = b.back;
  bk.shoulder_intake = 14;
  bk.centre_neck = {0, bl};
  bk.neck_point = {nw, hps_y};
  bk.shoulder_tip = bk.neck_point + Vec2{std::cos(slope), -std::sin(slope)} * (shoulder_len + bk.shoulder_intake);
  const double back_w = quarter - 8;
  bk.underarm = {back_w, bl - m.armscye_depth_mm - kUnderarmDropMm};
  bk.waist_side = {back_w - 15, 0};
  bk.armhole = cubic_points(bk.underarm, bk.underarm + Vec2{-55, 0}, bk.shoulder_tip + Vec2{-12, -95}, bk.shoulder_tip, 48);
  bk.neckline = quad_points(bk.neck_point, {nw * 0.55, bl}, bk.centre_neck, 24);
  bk.apex = {0.42 * back_w, bk.underarm.y + 40};
  bk.waist_intake = bk.waist_side.x - (waist_q - 5);
  b.side_length_mm = norm(bk.underarm - bk.waist_side);

  // Front: raised by the bust dart over the bust; its side seam is longer by the dart.
  HalfBlock& fr = b.front;
  b.bust_dart_mm = std::clamp(0.3 * (m.bust_mm - m.underbust_mm) - 10, 12.0, 45.0);
  const double front_w = quarter + 8;
  fr.neck_point = {nw, hps_y + b.bust_dart_mm};
  fr.centre_neck = {0, fr.neck_point.y - (nr + 25)};
  fr.shoulder_tip = fr.neck_point + Vec2{std::cos(slope_f), -std::sin(slope_f)} * shoulder_len;
  fr.waist_side = {front_w - 20, 0};
  const double front_side = b.side_length_mm + b.bust_dart_mm;
  fr.underarm = {front_w, std::sqrt(front_side * front_side - 20 * 20)};
  fr.armhole = cubic_points(fr.underarm, fr.underarm + Vec2{-65, 0}, fr.shoulder_tip + Vec2{-18, -75}, fr.shoulder_tip, 48);
  fr.neckline = quad_points(fr.neck_point, {nw, fr.centre_neck.y}, fr.centre_neck, 24);
  fr.apex = {m.bust_span_mm / 2, m.bust_above_waist_mm() + 0.6 * b.bust_dart_mm};
  fr.waist_intake = fr.waist_side.x - (waist_q + 5);
  b.bust_dart_centre_mm = front_side - kBustDartBelowUnderarmMm - b.bust_dart_mm / 2;

  // Below the waist both halves widen alike to the hip, then flare to the hem.
  const double widen = std::max(0.0, ((m.hips_mm + o.hip_ease_mm) / 2 - fr.waist_side.x - bk.waist_side.x) / 2);
  for (HalfBlock* h : {&fr, &bk}) {
    h->hem_y = o.hem_y_mm;
    h->hip_y = -m.waist_to_hip_mm;
    h->hip_side = h->waist_side + Vec2{widen, h->hip_y};
    if (o.hem_y_mm >= h->hip_y) {
      double f = o.hem_y_mm / h->hip_y;
      h->hem_side = h->waist_side + Vec2{widen * std::pow(f, 0.7), o.hem_y_mm};
    } else {
      h->hem_side = {h->hip_side.x + o.side_flare_mm, o.hem_y_mm};
    }
  }
  return b;
}

std::vector<Vec2> lower_side(const HalfBlock& h) {
  if (h.hem_y >= 0) return {h.waist_side};
  const bool below_hip = h.hem_y < h.hip_y;
  Vec2 end = below_hip ? h.hip_side : h.hem_side;
  double dy = std::abs(end.y);
  std::vector<Vec2> pts = cubic_points(h.waist_side, h.waist_side + Vec2{(end.x - h.waist_side.x) * 0.1, -0.4 * dy},
                                       end + Vec2{0, 0.35 * dy}, end, 24);
  if (below_hip) pts.push_back(h.hem_side);
  return pts;
}

std::pair<Piece, Piece> simple_top_halves(const BodiceBlock& b) {
  const HalfBlock& fr = b.front;
  const HalfBlock& bk = b.back;
  OutlineBuilder fb({0, 0});
  fb.line("waist", fr.waist_side).line("side", fr.underarm).polyline("armhole", fr.armhole);
  fb.line("shoulder", fr.neck_point).polyline("neckline", fr.neckline).line("cf", {0, 0});
  Piece front = make_piece("front_l", "front", fb.edges(), {fr.apex.x + 30, 30}, {fr.apex.x + 30, fr.underarm.y});
  // Bust dart from the side seam towards the bust point; waist dart up to just below it.
  {
    Vec2 mouth = fr.waist_side + normalized(fr.underarm - fr.waist_side) * b.bust_dart_centre_mm;
    Vec2 tip = fr.apex + normalized(mouth - fr.apex) * kDartShortOfApexMm;
    cut_dart(front, find_edge(front, "side"), b.bust_dart_centre_mm, b.bust_dart_mm, tip, "bust_dart");
    cut_dart(front, find_edge(front, "waist"), fr.apex.x, fr.waist_intake, fr.apex - Vec2{0, kDartShortOfApexMm},
             "waist_dart");
  }
  OutlineBuilder bb({0, 0});
  bb.line("waist", bk.waist_side).line("side", bk.underarm).polyline("armhole", bk.armhole);
  bb.line("shoulder", bk.neck_point).polyline("neckline", bk.neckline).line("cb", {0, 0});
  Piece back = make_piece("back_r", "back", bb.edges(), {bk.apex.x + 30, 30}, {bk.apex.x + 30, bk.underarm.y});
  {
    double shoulder_len = norm(bk.neck_point - bk.shoulder_tip);
    Vec2 mid = (bk.neck_point + bk.shoulder_tip) * 0.5;
    cut_dart(back, find_edge(back, "shoulder"), shoulder_len / 2, bk.shoulder_intake, mid + Vec2{0, -75}, "shoulder_dart");
    cut_dart(back, find_edge(back, "waist"), bk.apex.x, bk.waist_intake, bk.apex, "waist_dart");
  }
  return {front, back};
}

std::vector<Piece> princess_panels(const BodiceBlock& b) {
  const HalfBlock& fr = b.front;
  const HalfBlock& bk = b.back;
  const double hem_intake = 0;
  std::vector<Piece> out;

  // Front: the princess line runs from the shoulder (where the bust point projects onto it)
  // down through the bust point, the waist intake and the hem.
  {
    Vec2 s = project(fr.apex, fr.neck_point, fr.shoulder_tip);
    std::vector<Vec2> centre_edge = princess_lower(fr, hem_intake, -1);
    centre_edge.push_back(s);
    const double front_full = length(centre_edge);
    centre_edge = rounded(centre_edge, centre_edge.size() - 2, kPrincessFilletMm);
    const double front_loss = front_full - length(centre_edge);
    OutlineBuilder cb({0, fr.hem_y});
    cb.line("hem", centre_edge.front());
    cb.polyline("princess", std::vector<Vec2>(centre_edge.begin() + 1, centre_edge.end()));
    cb.line("shoulder", fr.neck_point).polyline("neckline", fr.neckline).line("cf", {0, fr.hem_y});
    out.push_back(make_piece("front_l", "front", cb.edges(), {fr.apex.x / 2, fr.hem_y + 40}, {fr.apex.x / 2, fr.centre_neck.y - 40}));

    // Side front: the part above the bust dart is turned about the bust point until the side
    // seam is as long as the back's; the dart's width moves to the princess seam at the
    // shoulder. The dart's legs are not equally far from the bust point, so a short step joins
    // the turned part: the turn is solved (bisection on the mouth width) for the exact length.
    Vec2 dir = normalized(fr.underarm - fr.waist_side);
    const double front_side = norm(fr.underarm - fr.waist_side), c = b.bust_dart_centre_mm;
    const Vec2 tip_pt = fr.apex;
    Vec2 d_low, d_up;
    double angle = 0;
    const auto solve = [&](double w) {
      d_low = fr.waist_side + dir * (c - w / 2);
      d_up = fr.waist_side + dir * (c + w / 2);
      angle = std::atan2(cross(d_up - tip_pt, d_low - tip_pt), dot(d_up - tip_pt, d_low - tip_pt));
      Vec2 joined = rotate_about(d_up, tip_pt, angle);
      return front_side - w + norm(joined - d_low);  // side seam length for mouth width w
    };
    double lo = 0, hi = 3 * b.bust_dart_mm;
    for (int i = 0; i < 60; ++i) {
      double mid = (lo + hi) / 2;
      (solve(mid) > b.side_length_mm ? lo : hi) = mid;
    }
    solve((lo + hi) / 2);
    const auto turn = [&](Vec2 p) { return rotate_about(p, tip_pt, angle); };
    std::vector<Vec2> side = lower_side(fr);
    std::reverse(side.begin(), side.end());
    side.push_back(d_low);
    side.push_back(turn(d_up));
    side.push_back(turn(fr.underarm));
    std::vector<Vec2> armhole;
    for (Vec2 p : fr.armhole) armhole.push_back(turn(p));
    Vec2 s_turned = turn(s);
    std::vector<Vec2> side_edge = princess_lower(fr, hem_intake, +1);
    std::reverse(side_edge.begin(), side_edge.end());
    side_edge.insert(side_edge.begin(), s_turned);
    side_edge = rounded_with_loss(side_edge, 1, front_loss);
    OutlineBuilder sb(side_edge.back());
    sb.line("hem", fr.hem_side);
    sb.polyline("side", std::vector<Vec2>(side.begin() + 1, side.end()));
    sb.polyline("armhole", std::vector<Vec2>(armhole.begin() + 1, armhole.end()));
    sb.line("shoulder", s_turned);
    sb.polyline("princess", std::vector<Vec2>(side_edge.begin() + 1, side_edge.end()));
    Vec2 g{(fr.apex.x + fr.waist_side.x) / 2, 0};
    out.push_back(make_piece("side_front_l", "side_front", sb.edges(), g + Vec2{0, fr.hem_y + 40}, g + Vec2{0, fr.underarm.y - 40}));
  }

  // Back: the princess line runs from the shoulder dart through the shoulder-blade point.
  {
    Vec2 foot = project(bk.apex, bk.neck_point, bk.shoulder_tip);
    Vec2 to_neck = normalized(bk.neck_point - bk.shoulder_tip);
    Vec2 s1 = foot + to_neck * (bk.shoulder_intake / 2), s2 = foot - to_neck * (bk.shoulder_intake / 2);
    std::vector<Vec2> centre_edge = princess_lower(bk, hem_intake, -1);
    centre_edge.push_back(s1);
    const double back_full = length(centre_edge);
    centre_edge = rounded(centre_edge, centre_edge.size() - 2, kPrincessFilletMm);
    const double back_loss = back_full - length(centre_edge);
    OutlineBuilder cb({0, bk.hem_y});
    cb.line("hem", centre_edge.front());
    cb.polyline("princess", std::vector<Vec2>(centre_edge.begin() + 1, centre_edge.end()));
    cb.line("shoulder", bk.neck_point).polyline("neckline", bk.neckline).line("cb", {0, bk.hem_y});
    out.push_back(make_piece("back_r", "back", cb.edges(), {bk.apex.x / 2, bk.hem_y + 40}, {bk.apex.x / 2, bk.centre_neck.y - 40}));

    std::vector<Vec2> side = lower_side(bk);
    std::reverse(side.begin(), side.end());
    side.push_back(bk.underarm);
    std::vector<Vec2> side_edge = princess_lower(bk, hem_intake, +1);
    std::reverse(side_edge.begin(), side_edge.end());
    side_edge.insert(side_edge.begin(), s2);
    side_edge = rounded_with_loss(side_edge, 1, back_loss);
    OutlineBuilder sb(side_edge.back());
    sb.line("hem", bk.hem_side);
    sb.polyline("side", std::vector<Vec2>(side.begin() + 1, side.end()));
    sb.polyline("armhole", std::vector<Vec2>(bk.armhole.begin() + 1, bk.armhole.end()));
    sb.line("shoulder", s2);
    sb.polyline("princess", std::vector<Vec2>(side_edge.begin() + 1, side_edge.end()));
    Vec2 g{(bk.apex.x + bk.waist_side.x) / 2, 0};
    out.push_back(make_piece("side_back_r", "side_back", sb.edges(), g + Vec2{0, bk.hem_y + 40}, g + Vec2{0, bk.underarm.y - 40}));
  }
  return out;
}

Piece draft_sleeve(const BodyMeasurements& m, double back_mm, double front_mm, double underarm_mm,
                   double hem_width_mm) {
  const double target = back_mm + front_mm;
  // The bicep: the upper arm and 70 mm of ease, and at least kBicepPerArmhole of the armhole.
  // The armhole grades less than the arm (16 against 25 mm a size), so with the ease alone the
  // cap of a small size is narrow and tall for its armhole; its crown then crumples on sewing.
  const double bicep = std::max(m.upper_arm_mm + 70, kBicepPerArmhole * target);
  // Cap half from the back underarm corner to the crown; the front half is its mirror image.
  const auto half_cap = [&](double h) {
    return cubic_points({bicep / 2, 0}, {0.75 * bicep / 2, 0.05 * h}, {0.42 * bicep / 2, h}, {0, h}, 48);
  };
  double lo = 20, hi = 2 * bicep;
  for (int i = 0; i < 60; ++i) {
    double mid = (lo + hi) / 2;
    (2 * length(half_cap(mid)) < target ? lo : hi) = mid;
  }
  std::vector<Vec2> cap = half_cap((lo + hi) / 2);
  for (int i = static_cast<int>(cap.size()) - 2; i >= 0; --i) cap.push_back({-cap[i].x, cap[i].y});
  OutlineBuilder b({-hem_width_mm / 2, -underarm_mm});
  b.line("hem", {hem_width_mm / 2, -underarm_mm}).line("underarm_right", {bicep / 2, 0});
  b.polyline("cap", std::vector<Vec2>(cap.begin() + 1, cap.end())).line("underarm_left", {-hem_width_mm / 2, -underarm_mm});
  Piece p = make_piece("sleeve_l", "sleeve", b.edges(), {0, -underarm_mm + 40}, {0, cap[cap.size() / 2].y - 40});
  add_notch(p, "cap", back_mm, "shoulder");
  return p;
}

Status sew_chains(Pattern& p, const std::vector<std::pair<std::string, std::string>>& chain_a,
                  const std::vector<std::pair<std::string, std::string>>& chain_b, const std::string& seam) {
  struct Link { int piece, edge; double start, len; };
  const auto resolve = [&](const std::vector<std::pair<std::string, std::string>>& chain, std::vector<Link>& out) -> Status {
    double acc = 0;
    for (const auto& [piece, edge] : chain) {
      int pi = find_piece(p, piece);
      int ei = pi < 0 ? -1 : find_edge(p.pieces[pi], edge);
      if (ei < 0) return fail(ErrorCode::kUnknownReference, "seam '" + seam + "': no edge '" + edge + "' on piece '" + piece + "'");
      double l = edge_length_mm(p.pieces[pi].edges[ei]);
      out.push_back({pi, ei, acc, l});
      acc += l;
    }
    return {};
  };
  std::vector<Link> a, b;
  if (auto s = resolve(chain_a, a); !s) return s;
  if (auto s = resolve(chain_b, b); !s) return s;
  const double la = a.back().start + a.back().len, lb = b.back().start + b.back().len;
  if (std::abs(la - lb) > kChainLengthTol * std::max(la, lb))
    return fail(ErrorCode::kInvalidPattern, "seam '" + seam + "': sides are " + std::to_string(la) + " mm and " +
                                                std::to_string(lb) + " mm long");
  // Breakpoints in A's arc length: A's edge ends and B's (B runs the other way).
  std::vector<double> cuts{0, la};
  for (const Link& l : a) cuts.push_back(l.start);
  for (const Link& l : b) cuts.push_back((lb - l.start) * la / lb);
  std::sort(cuts.begin(), cuts.end());
  std::vector<double> u;
  for (double c : cuts)
    if (u.empty() || c - u.back() > 0.05) u.push_back(c);
  u.back() = la;
  const auto locate = [](const std::vector<Link>& ls, double s) {
    for (size_t i = 0; i < ls.size(); ++i)
      if (s < ls[i].start + ls[i].len) return i;
    return ls.size() - 1;
  };
  const auto span = [](const Link& l, double s0, double s1) {
    double from = std::max(0.0, s0 - l.start), to = s1 - l.start;
    return EdgeSpan{l.piece, l.edge, from < 0.05 ? 0.0 : from, to > l.len - 0.05 ? -1.0 : to};
  };
  for (size_t k = 0; k + 1 < u.size(); ++k) {
    double s0 = u[k], s1 = u[k + 1], mid = (s0 + s1) / 2;
    const Link& ea = a[locate(a, mid)];
    double t0 = lb - s1 * lb / la, t1 = lb - s0 * lb / la;
    const Link& eb = b[locate(b, (t0 + t1) / 2)];
    p.stitches.push_back(Stitch{span(ea, s0, s1), span(eb, t0, t1), false});
  }
  return {};
}

Placement3d front_placement(double r, double waist_y) { return Placement3d{{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, waist_y, r}}; }

Placement3d back_placement(double r, double waist_y) { return Placement3d{{-1, 0, 0, 0, 1, 0, 0, 0, -1}, {0, waist_y, -r}}; }

}  // namespace tp::geometry::samples::internal
