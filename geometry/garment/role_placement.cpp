// geometry/garment/role_placement.cpp: body landmarks from slices, and a placement per piece role.
#include "geometry/garment/role_placement.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

namespace tp::geometry {
namespace {

// Slices and rays step this far (mm).
constexpr double kSliceStep_mm = 10;
constexpr double kRayStep_mm = 4;
// Pieces start this far outside the torso surface.
constexpr double kGap_mm = 30;
// A sleeve's cap starts this far down the arm from the shoulder point.
constexpr double kCapDrop_mm = 20;
// The arm's axis is found from its centres this far below the shoulders (mm).
constexpr double kArmSlice1_mm = 200;
constexpr double kArmSlice2_mm = 320;
constexpr double kArmSliceStep_mm = 40;
constexpr double kArmSliceLast_mm = 440;

bool inside(const BodySdf& b, Vec3 p) { return b.query(p).distance_mm < 0; }

// Distance from `from` along unit `dir` to the first point outside the body (0 if `from` is out).
double extent(const BodySdf& b, Vec3 from, Vec3 dir, double max_mm) {
  double s = 0;
  while (s < max_mm && inside(b, from + dir * s)) s += kRayStep_mm;
  return s;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool has(const std::string& s, const char* w) { return s.find(w) != std::string::npos; }

bool lower_garment(const Pattern& pattern) {
  bool sleeve = false, lower_piece = false;
  for (const Piece& p : pattern.pieces) {
    const std::string n = lower(p.name + " " + p.role);
    sleeve = sleeve || has(n, "sleeve");
    lower_piece = lower_piece || has(n, "waistband") || has(n, "skirt") || has(n, "pant") || has(n, "trouser");
  }
  return lower_piece && !sleeve;
}

Box2 piece_box(const Piece& p) {
  Box2 b;
  for (const Edge& e : p.edges)
    for (Vec2 q : e.points_mm) b.add(q);
  return b;
}

// A placement whose piece x runs along `cx`, piece y along `cy` (unit, orthogonal), that puts
// the piece point `at_piece` at `at_world`.
Placement3d frame(Vec3 cx, Vec3 cy, Vec2 at_piece, Vec3 at_world) {
  Vec3 cz = cross(cx, cy);
  Placement3d pl;
  pl.rotation = {cx.x, cy.x, cz.x, cx.y, cy.y, cz.y, cx.z, cy.z, cz.z};
  pl.translation_mm = at_world - (cx * at_piece.x + cy * at_piece.y);
  return pl;
}

Vec2 edge_mid(const Piece& p, int e) {
  const auto& pts = p.edges[static_cast<size_t>(e)].points_mm;
  return (pts.front() + pts.back()) * 0.5;
}

// The longest edge of band piece `i` (a waistband) that stitches join to other pieces, or -1.
int band_sewn_edge(const Pattern& pattern, int i) {
  int best = -1;
  double best_len = 0;
  for (const Stitch& st : pattern.stitches)
    for (const auto& [mine, other] : {std::pair{st.a, st.b}, std::pair{st.b, st.a}})
      if (mine.piece == i && other.piece != i) {
        const auto& pts = pattern.pieces[static_cast<size_t>(i)].edges[static_cast<size_t>(mine.edge)].points_mm;
        const double len = norm(pts.back() - pts.front());
        if (len > best_len) best = mine.edge, best_len = len;
      }
  return best;
}

// The edge of piece `i` a stitch joins to piece `j` (the first such stitch), or -1.
int edge_sewn_to(const Pattern& pattern, int i, int j) {
  for (const Stitch& st : pattern.stitches) {
    if (st.a.piece == i && st.b.piece == j) return st.a.edge;
    if (st.b.piece == i && st.a.piece == j) return st.b.edge;
  }
  return -1;
}

Vec3 place(const Placement3d& pl, Vec2 q) {
  const auto& r = pl.rotation;
  return Vec3{r[0] * q.x + r[1] * q.y, r[3] * q.x + r[4] * q.y, r[6] * q.x + r[7] * q.y} + pl.translation_mm;
}

}  // namespace

BodyLandmarks find_landmarks(const BodySdf& body) {
  BodyLandmarks L;
  const Box3& bb = body.box();
  L.axis = {(bb.min.x + bb.max.x) / 2, 0, (bb.min.z + bb.max.z) / 2};
  L.top_y = bb.max.y;
  const double reach = std::max(bb.max.x - bb.min.x, bb.max.z - bb.min.z);
  auto at = [&](double y) { return Vec3{L.axis.x, y, L.axis.z}; };
  auto width = [&](double y) {
    return std::min(extent(body, at(y), {1, 0, 0}, reach), extent(body, at(y), {-1, 0, 0}, reach));
  };
  // The torso's axis at mid height (the box centre may be off it, e.g. an arm raised).
  {
    const double y = bb.min.y + 0.6 * (bb.max.y - bb.min.y);
    if (inside(body, at(y))) {
      double xr = extent(body, at(y), {1, 0, 0}, reach), xl = extent(body, at(y), {-1, 0, 0}, reach);
      double zf = extent(body, at(y), {0, 0, 1}, reach), zb = extent(body, at(y), {0, 0, -1}, reach);
      L.axis.x += (xr - xl) / 2;
      L.axis.z += (zf - zb) / 2;
    }
  }
  // Shoulders: going down from the top, the slice first widens past 2.2 times the neck.
  double neck = 0;
  for (double y = bb.max.y - 40; y > bb.min.y; y -= kSliceStep_mm) {
    double w = width(y);
    if (w <= 0) continue;
    if (neck == 0) neck = w;
    neck = std::min(neck, w);
    if (w > 2.2 * neck) {
      L.shoulder_y = y;
      break;
    }
  }
  if (L.shoulder_y == 0) L.shoulder_y = bb.min.y + 0.82 * (bb.max.y - bb.min.y);
  // Waist: the narrowest slice (width plus depth) well below the shoulders; hips: the widest below it.
  double best = 1e300;
  L.waist_y = L.shoulder_y - 400;
  for (double y = L.shoulder_y - 300; y >= L.shoulder_y - 520 && y > bb.min.y; y -= kSliceStep_mm) {
    double s = width(y) + extent(body, at(y), {0, 0, 1}, reach) + extent(body, at(y), {0, 0, -1}, reach);
    if (s > 0 && s < best) best = s, L.waist_y = y;
  }
  double widest = -1;
  L.hip_y = L.waist_y - 200;
  for (double y = L.waist_y - 150; y >= L.waist_y - 250 && y > bb.min.y; y -= kSliceStep_mm) {
    double s = width(y);
    if (s > widest) widest = s, L.hip_y = y;
  }
  const double bust_y = L.shoulder_y - 0.35 * (L.shoulder_y - L.waist_y);
  L.front_z = L.axis.z + extent(body, at(bust_y), {0, 0, 1}, reach);
  L.back_z = L.axis.z - extent(body, at(bust_y), {0, 0, -1}, reach);
  L.waist_front_z = L.axis.z + extent(body, at(L.waist_y), {0, 0, 1}, reach);
  L.waist_back_z = L.axis.z - extent(body, at(L.waist_y), {0, 0, -1}, reach);
  L.side_x = width(bust_y);
  const double shoulder_half = width(L.shoulder_y - kSliceStep_mm);
  L.shoulder_l = {L.axis.x + shoulder_half, L.shoulder_y, L.axis.z};
  L.shoulder_r = {L.axis.x - shoulder_half, L.shoulder_y, L.axis.z};
  L.arm_top_l = L.shoulder_l;
  L.arm_top_r = L.shoulder_r;
  // Arms: below the shoulders, the first solid beyond a gap outside the torso's side, its centre
  // on a horizontal ray. Two such centres (200 and 320 mm below the shoulders) give the arm's
  // axis; with one, the axis runs from the shoulder point to it (a raised arm's second slice may
  // miss it). A line from the shoulder point alone tilted a 45-degree dress-form arm to 32 degrees
  // and left sleeve hems 60 mm off the arm.
  auto arm_centre = [&](int side, double y, Vec3& centre) {
    const Vec3 dir{static_cast<double>(side), 0, 0};
    const Vec3 start = at(y);
    double s = extent(body, start, dir, reach);
    while (s < reach && !inside(body, start + dir * s)) s += kRayStep_mm;
    if (s >= reach) return false;
    const double run = extent(body, start + dir * s, dir, reach);
    centre = start + dir * (s + run / 2);
    // The arm need not be centred on the torso's axis front to back (a dress form's is 8 mm behind).
    centre.z += (extent(body, centre, {0, 0, 1}, reach) - extent(body, centre, {0, 0, -1}, reach)) / 2;
    return true;
  };
  // An arm closer to the body is still joined to the torso 200 mm down: the slices go lower
  // (kArmSliceStep_mm at a time) until one finds it apart, the second slice as far below that.
  for (int side : {1, -1}) {
    Vec3 a1, a2;
    double depth = kArmSlice1_mm;
    while (depth <= kArmSliceLast_mm && !arm_centre(side, L.shoulder_y - depth, a1)) depth += kArmSliceStep_mm;
    if (depth > kArmSliceLast_mm) continue;
    const Vec3 from = side > 0 ? L.shoulder_l : L.shoulder_r;
    Vec3& dir = side > 0 ? L.arm_dir_l : L.arm_dir_r;
    Vec3& top = side > 0 ? L.arm_top_l : L.arm_top_r;
    if (arm_centre(side, L.shoulder_y - depth - (kArmSlice2_mm - kArmSlice1_mm), a2) && norm(a2 - a1) > 0 &&
        (a2.x - a1.x) * side > 0) {
      dir = normalized(a2 - a1);
      // Where the axis passes the shoulder point: the sleeve cap's top.
      top = a1 + dir * dot(from - a1, dir);
    } else if (norm(a1 - from) > 0) {
      dir = normalized(a1 - from);
      top = from;
    }
  }
  return L;
}

std::vector<Placement3d> role_placements(const Pattern& pattern, const BodySdf& body) {
  std::vector<Placement3d> out(pattern.pieces.size());
  if (std::all_of(pattern.pieces.begin(), pattern.pieces.end(), [](const Piece& p) { return p.placement.has_value(); })) {
    for (size_t i = 0; i < out.size(); ++i) out[i] = *pattern.pieces[i].placement;
    return out;
  }
  const BodyLandmarks L = find_landmarks(body);
  const bool lower_body = lower_garment(pattern);
  const Vec3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
  for (size_t i = 0; i < pattern.pieces.size(); ++i) {
    const Piece& p = pattern.pieces[i];
    if (p.placement) {
      out[i] = *p.placement;
      continue;
    }
    const Box2 b = piece_box(p);
    const std::string role = lower(p.role + " " + p.name);
    // A piece of a mirrored pair sits beside its twin: the drafted one on the wearer's left.
    bool paired = false;
    for (const Piece& q : pattern.pieces)
      paired = paired || (&q != &p && !q.source_piece.empty() && q.source_piece == p.source_piece);
    const double top_y = lower_body ? L.waist_y + 20 : L.shoulder_y + 40;
    if (has(role, "sleeve")) continue;  // placed below, beside the pieces they are sewn to
    if (has(role, "waistband") || has(role, "cuff") || has(role, "belt")) {
      const double z = L.waist_front_z + kGap_mm;
      // Lengthwise round the body, the edge sewn to the garment at the bottom, at the garment's
      // top (initial_placement rolls it into a ring of its own length).
      const int sewn = band_sewn_edge(pattern, static_cast<int>(i));
      if (sewn >= 0) {
        const Vec2 c{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2};
        const Vec2 m = edge_mid(p, sewn);
        const bool lengthwise_y = b.height() > b.width();
        const bool low = lengthwise_y ? m.x < c.x : m.y < c.y;
        Vec3 cx = lengthwise_y ? (low ? Y : -Y) : (low ? X : -X);
        Vec3 cy = lengthwise_y ? (low ? -X : X) : (low ? Y : -Y);
        const Vec2 anchor = lengthwise_y ? Vec2{m.x, c.y} : Vec2{c.x, m.y};
        out[i] = frame(cx, cy, anchor, Vec3{L.axis.x, lower_body ? top_y : L.waist_y, z});
        continue;
      }
      out[i] = frame(X, Y, Vec2{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2}, Vec3{L.axis.x, L.waist_y, z});
      continue;
    }
    const bool back = has(role, "back") && !has(role, "front");
    const double z = back ? std::min(L.back_z, L.waist_back_z) - kGap_mm : std::max(L.front_z, L.waist_front_z) + kGap_mm;
    // Fronts face +z (piece x to the wearer's left), backs -z (piece x to the wearer's right).
    const Vec3 cx = back ? -X : X;
    Vec2 anchor{(b.min.x + b.max.x) / 2, b.max.y};
    Vec3 world{L.axis.x, top_y, z};
    if (paired) {
      // The edge sewn to its twin (centre front or back) goes on the centre line; without such a
      // stitch the drafted (left) piece's centre edge, seen from outside, is taken to be there.
      int twin_edge = -1;
      for (size_t j = 0; j < pattern.pieces.size() && twin_edge < 0; ++j)
        if (j != i && pattern.pieces[j].source_piece == p.source_piece)
          twin_edge = edge_sewn_to(pattern, static_cast<int>(i), static_cast<int>(j));
      if (twin_edge >= 0) {
        anchor.x = edge_mid(p, twin_edge).x < (b.min.x + b.max.x) / 2 ? b.min.x : b.max.x;
      } else {
        const bool drafted = !p.mirrored;
        anchor.x = back ? (drafted ? b.max.x : b.min.x) : (drafted ? b.min.x : b.max.x);
      }
    }
    if (has(role, "collar") || has(role, "hood")) world.y = L.top_y;
    if (has(role, "pocket")) world.y = lower_body ? L.hip_y : (L.shoulder_y + L.waist_y) / 2;
    out[i] = frame(cx, Y, anchor, world);
  }
  // Sleeves go on the arm beside the armholes they are sewn to (the stitch graph), else by
  // copy: the drafted sleeve on the wearer's left.
  for (size_t i = 0; i < pattern.pieces.size(); ++i) {
    const Piece& p = pattern.pieces[i];
    if (p.placement || !has(lower(p.role + " " + p.name), "sleeve")) continue;
    const Box2 b = piece_box(p);
    double x_sum = 0;
    int x_count = 0;
    for (size_t j = 0; j < pattern.pieces.size(); ++j) {
      if (j == i || has(lower(pattern.pieces[j].role + " " + pattern.pieces[j].name), "sleeve")) continue;
      int e = edge_sewn_to(pattern, static_cast<int>(j), static_cast<int>(i));
      if (e < 0) continue;
      x_sum += place(out[j], edge_mid(pattern.pieces[j], e)).x - L.axis.x;
      ++x_count;
    }
    const bool left = x_count ? x_sum > 0 : !p.mirrored;

    const Vec3 shoulder = left ? L.arm_top_l : L.arm_top_r;
    const Vec3 down = left ? L.arm_dir_l : L.arm_dir_r;
    const Vec3 up = -down;
    // Outward from the body, perpendicular to the arm, in the arm's vertical plane.
    Vec3 out_dir = normalized(cross(up, Z) * (left ? -1.0 : 1.0));
    if (dot(out_dir, Vec3{left ? 1.0 : -1.0, 0, 0}) < 0) out_dir = -out_dir;
    const double r = b.width() / (2 * std::numbers::pi);
    const double len = b.height();
    const Vec3 centre = shoulder + down * (kCapDrop_mm + len / 2) + out_dir * r;
    out[i] = frame(cross(up, out_dir), up, Vec2{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2}, centre);
  }
  return out;
}

}  // namespace tp::geometry
