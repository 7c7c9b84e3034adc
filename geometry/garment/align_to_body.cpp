// geometry/garment/align_to_body.cpp: placed pieces' bounds against the body's axis, waist and shoulders.
#include "geometry/garment/align_to_body.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "geometry/pattern/placement.h"

namespace tp::geometry {
namespace {

// Proportions of a standing body (heights above the floor as a fraction of stature).
constexpr double kWaistHeight = 0.62;
constexpr double kShoulderHeight = 0.82;
// A top's placed bounds start this far above the shoulders (neckline and shoulder slope).
constexpr double kTopAboveShoulder_mm = 60;
// Placed pieces spanning more than this many body heights, or less than this fraction, are in
// other units.
constexpr double kMaxSpanBodies = 2.5;
constexpr double kMinSpanBodies = 0.02;
// The pieces' vertical overlap with the body, as a fraction of their own height, to count as on it.
constexpr double kMinHeightOverlap = 0.5;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool lower_garment(const Pattern& pattern) {
  int lower_pieces = 0, upper_pieces = 0;
  for (const Piece& p : pattern.pieces) {
    const std::string n = lower(p.name + " " + p.role + " " + pattern.name);
    bool lo = n.find("skirt") != std::string::npos || n.find("pant") != std::string::npos ||
              n.find("trouser") != std::string::npos || n.find("waistband") != std::string::npos ||
              n.find("wb") != std::string::npos || n.find("leg") != std::string::npos;
    bool up = n.find("sleeve") != std::string::npos || n.find("torso") != std::string::npos ||
              n.find("collar") != std::string::npos || n.find("bodice") != std::string::npos ||
              n.find("tee") != std::string::npos || n.find("shirt") != std::string::npos;
    lower_pieces += lo && !up;
    upper_pieces += up;
  }
  return lower_pieces > 0 && upper_pieces == 0;
}

Box3 placed_bounds(const Pattern& pattern, double* front_z, double* back_z) {
  Box3 b;
  double fz = 0, bz = 0;
  int nf = 0, nb = 0;
  for (const Piece& p : pattern.pieces) {
    if (!p.placement) continue;
    Vec3 c{};
    int n = 0;
    for (const Edge& e : p.edges)
      for (Vec2 q : e.points_mm) {
        Vec3 x = place_point(*p.placement, q);
        b.add(x);
        c += x;
        ++n;
      }
    if (n == 0) continue;
    c = c / n;
    if (p.role == "front") fz += c.z, ++nf;
    if (p.role == "back") bz += c.z, ++nb;
  }
  *front_z = nf ? fz / nf : 0;
  *back_z = nb ? bz / nb : 0;
  if (!(nf && nb)) *front_z = *back_z = 0;
  return b;
}

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

}  // namespace

double waist_height_mm(const Box3& b) { return b.min.y + kWaistHeight * (b.max.y - b.min.y); }
double shoulder_height_mm(const Box3& b) { return b.min.y + kShoulderHeight * (b.max.y - b.min.y); }

Result<BodyAlignment> align_to_body(Pattern& pattern, const BodySdf& body) {
  BodyAlignment out;
  if (std::none_of(pattern.pieces.begin(), pattern.pieces.end(), [](const Piece& p) { return p.placement.has_value(); }))
    return out;
  const Box3& bb = body.box();
  const double body_h = bb.max.y - bb.min.y;
  const Vec3 axis{(bb.min.x + bb.max.x) / 2, 0, (bb.min.z + bb.max.z) / 2};
  double front_z = 0, back_z = 0;
  Box3 g = placed_bounds(pattern, &front_z, &back_z);
  const double span = std::max({g.max.x - g.min.x, g.max.y - g.min.y, g.max.z - g.min.z});
  if (span > kMaxSpanBodies * body_h || span < kMinSpanBodies * body_h)
    return fail(ErrorCode::kInvalidPattern, "pattern '" + pattern.name + "': placed pieces span " + mm(span) +
                                                " mm against a body " + mm(body_h) +
                                                " mm tall: placement in other units than the pattern says");
  out.garment_kind = lower_garment(pattern) ? "lower" : "upper";

  const double overlap = std::min(g.max.y, bb.max.y) - std::max(g.min.y, bb.min.y);
  const bool around_axis = g.min.x <= axis.x && axis.x <= g.max.x && g.min.z <= axis.z && axis.z <= g.max.z;
  const bool on_height = overlap >= kMinHeightOverlap * (g.max.y - g.min.y);
  const bool fronts_behind = front_z < back_z;
  if (around_axis && on_height && !fronts_behind) return out;

  // Turn 180 deg about the body's vertical axis when the fronts sit behind the backs.
  if (fronts_behind) {
    for (Piece& p : pattern.pieces) {
      if (!p.placement) continue;
      auto& r = p.placement->rotation;
      for (int c = 0; c < 3; ++c) r[c] = -r[c], r[6 + c] = -r[6 + c];
      Vec3& t = p.placement->translation_mm;
      t = Vec3{2 * axis.x - t.x, t.y, 2 * axis.z - t.z};
    }
    out.turned = true;
    g = placed_bounds(pattern, &front_z, &back_z);
  }
  // Centre on the body's axis, top at the waist or above the shoulders.
  const double top = out.garment_kind == "lower" ? waist_height_mm(bb) : shoulder_height_mm(bb) + kTopAboveShoulder_mm;
  const Vec3 offset{axis.x - (g.min.x + g.max.x) / 2, top - g.max.y, axis.z - (g.min.z + g.max.z) / 2};
  for (Piece& p : pattern.pieces)
    if (p.placement) p.placement->translation_mm += offset;
  out.moved = true;
  out.offset_mm = offset;
  out.reason = std::string(fronts_behind ? "fronts were behind the backs (mirrored axis): turned 180 deg; " : "") +
               (around_axis && on_height ? "" : "placed pieces did not surround the body (" +
                                                    std::string(!around_axis ? "off its axis" : "") +
                                                    (!around_axis && !on_height ? ", " : "") +
                                                    (!on_height ? "beside its height" : "") + "); ") +
               "moved by (" + mm(offset.x) + ", " + mm(offset.y) + ", " + mm(offset.z) + ") mm to the body's " +
               (out.garment_kind == "lower" ? "waist" : "shoulders");
  return out;
}

}  // namespace tp::geometry
