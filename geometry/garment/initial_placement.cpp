// geometry/garment/initial_placement.cpp: pieces placed and rolled around the body before sewing.
#include "geometry/garment/initial_placement.h"

#include "geometry/garment/role_placement.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

namespace tp::geometry {
namespace {

// Pieces nearer than this to their roll axis, or rolled further round than this, stay flat.
constexpr double kMinRollRadiusMm = 30;
constexpr double kMaxRollAngle = 0.8 * std::numbers::pi;
// A rolled piece placed by its role keeps this far from the body (mm).
constexpr double kRollClearance_mm = 25;

Vec3 rotate(const Placement3d& pl, Vec2 p) {
  const auto& r = pl.rotation;
  return Vec3{r[0] * p.x + r[1] * p.y, r[3] * p.x + r[4] * p.y, r[6] * p.x + r[7] * p.y} + pl.translation_mm;
}

// Rolls the flat points `pts` (in a plane through `foot`, `inward` its unit normal towards the
// axis) onto the cylinder of radius r whose axis is foot + inward * r, direction d (in the
// plane). The tangency line passes through `foot`. Isometric: arc length s becomes angle s / r.
void roll(std::vector<Vec3>& pts, Vec3 foot, Vec3 d, Vec3 inward, double r) {
  Vec3 t = cross(d, inward);
  Vec3 axis = foot + inward * r;
  for (Vec3& p : pts) {
    Vec3 q = p - foot;
    double u = dot(q, d), s = dot(q, t);
    double a = s / r;
    p = axis + d * u - inward * (r * std::cos(a)) + t * (r * std::sin(a));
  }
}

// A piece sewn to itself between two edges far apart across its width is a tube.
bool is_tube(const Pattern& pattern, int piece, double width_mm) {
  for (const Stitch& st : pattern.stitches) {
    if (st.a.piece != piece || st.b.piece != piece || st.a.edge == st.b.edge) continue;
    const auto mid = [&](const EdgeSpan& sp) {
      const auto& pts = pattern.pieces[piece].edges[sp.edge].points_mm;
      return (pts.front() + pts.back()) * 0.5;
    };
    if (std::abs(mid(st.a).x - mid(st.b).x) > 0.6 * width_mm) return true;
  }
  return false;
}

// The largest distance from the body's vertical axis (through `centre`) to the torso surface
// between heights lo and hi: rays from the axis in 24 directions every 20 mm of height, each to
// its first exit (arms beyond a gap do not count).
double body_radius(const BodySdf& body, Vec3 centre, double lo, double hi) {
  constexpr double kStep_mm = 4, kMax_mm = 800;
  double r = 0;
  for (double y = lo; y <= hi; y += 20)
    for (int k = 0; k < 24; ++k) {
      const double a = 2 * std::numbers::pi * k / 24;
      const Vec3 from{centre.x, y, centre.z}, dir{std::cos(a), 0, std::sin(a)};
      double t = 0;
      while (t < kMax_mm && body.query(from + dir * t).distance_mm < 0) t += kStep_mm;
      if (t < kMax_mm) r = std::max(r, t);
    }
  return r;
}

// Waistbands and belts go round the body lengthwise.
bool is_band(const Piece& p) {
  std::string n = p.role + " " + p.name;
  for (char& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return n.find("waistband") != std::string::npos || n.find("belt") != std::string::npos;
}

// A piece to be rolled round the body's vertical axis: where, and the span it covers.
struct AxisRoll {
  size_t piece;
  Vec3 axis_pt, d, inward;
  double r;                       // roll radius (mm), the piece's distance from the axis unless moved out
  double r0;                      // the distance it was placed at (set by fit_rolls_round_axis)
  double s_lo, s_hi, y_lo, y_hi;  // extent across (along the roll) and in height (mm)
  std::map<int, std::pair<double, double>> rows;  // extent across per kRowMm of height
};

// Height of the rows whose widths fit_rolls_round_axis adds up (mm).
constexpr double kRowMm = 20;

// Moves pieces out so that those sharing a height fit round the axis: at each height the arcs
// (width / radius) of the pieces hanging there may add up to at most one turn. Radii only grow.
void fit_rolls_round_axis(std::vector<AxisRoll>& rolls) {
  for (AxisRoll& a : rolls) a.r0 = a.r;
  if (rolls.size() < 2) return;
  std::map<int, std::vector<std::pair<AxisRoll*, double>>> by_row;  // row: pieces and widths
  for (AxisRoll& a : rolls)
    for (const auto& [row, span] : a.rows) by_row[row].push_back({&a, span.second - span.first});
  constexpr double kTurn = 2 * std::numbers::pi;
  for (const auto& row_pieces : by_row) {
    const auto& at = row_pieces.second;  // not a structured binding: the lambda below captures it
    if (at.size() < 2) continue;
    const auto turn = [&](double r) {
      double sum = 0;
      for (const auto& [a, width] : at) sum += width / std::max(a->r, r);
      return sum;
    };
    if (turn(0) <= kTurn) continue;
    double r_lo = 0, r_hi = 1;
    while (turn(r_hi) > kTurn) r_hi *= 2;
    for (int it = 0; it < 60; ++it) {
      const double mid = (r_lo + r_hi) / 2;
      (turn(mid) > kTurn ? r_lo : r_hi) = mid;
    }
    for (const auto& [a, width] : at) a->r = std::max(a->r, r_hi);
  }
}

}  // namespace

std::vector<std::vector<Vec3>> initial_placement(const Pattern& pattern, const PatternMesh& meshes, const BodySdf& body,
                                                 double clearance_mm, PushOutStats* stats) {
  const Box3& bb = body.box();
  const Vec3 centre{(bb.min.x + bb.max.x) / 2, 0, (bb.min.z + bb.max.z) / 2};
  std::vector<std::vector<Vec3>> out(pattern.pieces.size());
  // Pieces without a placement get one from their role and the body's landmarks.
  const std::vector<Placement3d> placements = role_placements(pattern, body);
  std::vector<AxisRoll> rolls;

  for (size_t pi = 0; pi < pattern.pieces.size(); ++pi) {
    const PieceMesh& m = meshes.pieces[pi];
    Box2 pb;
    for (Vec2 v : m.vertices_mm) pb.add(v);
    const Vec2 pc{(pb.min.x + pb.max.x) / 2, (pb.min.y + pb.max.y) / 2};
    std::vector<Vec3>& pts = out[pi];
    const Placement3d& pl = placements[pi];
    for (Vec2 v : m.vertices_mm) pts.push_back(rotate(pl, v));
    const Vec3 origin = rotate(pl, {0, 0});
    Vec3 d = rotate(pl, {0, 1}) - origin, n = cross(rotate(pl, {1, 0}) - origin, d);
    d = normalized(d);
    n = normalized(n);
    Vec3 c3 = rotate(pl, pc);
    const Vec3 ex = normalized(rotate(pl, {1, 0}) - origin);
    const bool y_round = std::abs(d.y) < 0.2 && std::abs(ex.y) > 0.8;
    const bool x_round = std::abs(ex.y) < 0.2 && std::abs(d.y) > 0.8;
    if (is_band(pattern.pieces[pi]) && (x_round || y_round)) {
      // A band lying lengthwise round the body: a ring of its own length round the vertical axis,
      // its middle where it was placed (in front).
      const Vec3 round = y_round ? d : ex, up = y_round ? ex : d;
      const double len = std::abs(dot(rotate(pl, pb.max) - rotate(pl, pb.min), round));
      const double r = len / (2 * std::numbers::pi);
      Vec3 outward = Vec3{c3.x - centre.x, 0, c3.z - centre.z};
      outward = norm(outward) > 0 ? normalized(outward) : Vec3{0, 0, 1};
      const Vec3 foot = Vec3{centre.x, c3.y, centre.z} + outward * r;
      for (Vec3& p : pts) p = p + (foot - c3);
      roll(pts, foot, up, -outward, r);
    } else if (is_tube(pattern, static_cast<int>(pi), pb.width())) {
      // Roll into a tube of its own width around an axis on the body's side of the piece.
      Vec3 to_body = Vec3{centre.x, c3.y, centre.z} - c3;
      Vec3 inward = dot(to_body, n) >= 0 ? n : -n;
      roll(pts, c3, d, inward, pb.width() / (2 * std::numbers::pi));
    } else if (std::abs(d.y) > 0.8) {
      // Roll around the body's vertical axis if the piece faces it and does not wrap too far.
      Vec3 axis_pt{centre.x, c3.y, centre.z};
      double rs = dot(c3 - axis_pt, n);
      Vec3 inward = rs >= 0 ? -n : n;
      double r = std::abs(rs);
      if (!pattern.pieces[pi].placement) {
        // A piece placed by its role is placed at one level (the waist of a skirt): rolled, it
        // must clear the body at every level it hangs over (the hips), or it starts inside.
        double lo = 1e300, hi = -1e300;
        for (const Vec3& p : pts) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
        const double clear = body_radius(body, centre, lo, hi) + kRollClearance_mm;
        if (clear > r) {
          for (Vec3& p : pts) p = p - inward * (clear - r);
          c3 = c3 - inward * (clear - r);
          r = clear;
        }
      }
      AxisRoll ar{pi, axis_pt, d, inward, r, r, 1e300, -1e300, 1e300, -1e300, {}};
      const Vec3 foot = axis_pt - inward * r, t = cross(d, inward);
      for (const Vec3& p : pts) {
        const double s = dot(p - foot, t);
        ar.s_lo = std::min(ar.s_lo, s), ar.s_hi = std::max(ar.s_hi, s);
        ar.y_lo = std::min(ar.y_lo, p.y), ar.y_hi = std::max(ar.y_hi, p.y);
        auto [it, fresh] = ar.rows.try_emplace(static_cast<int>(std::floor(p.y / kRowMm)), s, s);
        if (!fresh) it->second = {std::min(it->second.first, s), std::max(it->second.second, s)};
      }
      // Pieces too near the axis or reaching too far round it (a T-pose sleeve facing forward) stay flat.
      const double s_max = std::max(std::abs(ar.s_lo), std::abs(ar.s_hi));
      if (r > kMinRollRadiusMm && s_max / r < kMaxRollAngle) rolls.push_back(ar);
    }
  }
  // Pieces rolled round the body's axis at heights they share must fit round it side by side:
  // a front and a back each rolled at its own distance can wrap past the sides into each other
  // (GarmentCode 2021's skirt_2_panels: each panel 666 mm wide at 155-187 mm from the axis), so
  // their sides' seams start crossed. Where the arcs would add up to more than a turn, the
  // nearer pieces move out to the radius at which they just fit.
  fit_rolls_round_axis(rolls);
  for (const AxisRoll& ar : rolls) {
    std::vector<Vec3>& pts = out[ar.piece];
    const Vec3 foot = ar.axis_pt - ar.inward * ar.r;
    const Vec3 shift = ar.inward * -(ar.r - ar.r0);
    for (Vec3& p : pts) p = p + shift;
    roll(pts, foot, ar.d, ar.inward, ar.r);
  }
  // Whatever placed them (their own placement, a role, a roll), no piece starts inside the body.
  push_out_of_body(out, meshes, body, clearance_mm, kPushRadius_mm, stats);
  return out;
}

}  // namespace tp::geometry
