// geometry/pattern/darts.cpp: dart tips are sharp reflex vertices between legs of equal length.
#include "geometry/pattern/darts.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tp::geometry {

int detect_darts(Piece& piece) {
  const int n = static_cast<int>(piece.edges.size());
  if (n < 3) return 0;
  std::vector<bool> used(n, false);
  for (const Dart& d : piece.darts) {
    if (d.leg_a >= 0 && d.leg_a < n) used[d.leg_a] = true;
    if (d.leg_b >= 0 && d.leg_b < n) used[d.leg_b] = true;
  }
  const double max_open = kMaxDartOpening_deg * std::numbers::pi / 180;
  int added = 0;
  for (int a = 0; a < n; ++a) {
    int b = (a + 1) % n;
    if (used[a] || used[b]) continue;
    const Edge& in = piece.edges[a];
    const Edge& out = piece.edges[b];
    if (in.points_mm.size() < 2 || out.points_mm.size() < 2) continue;
    // The legs' chords from the tip to the two ends of the dart's mouth: curved legs make the
    // tangents at the tip a poor measure of the opening.
    Vec2 tip = in.points_mm.back();
    Vec2 ua = in.points_mm.front() - tip, ub = out.points_mm.back() - tip;
    if (norm(ua) == 0 || norm(ub) == 0) continue;
    double opening = std::acos(std::clamp(dot(normalized(ua), normalized(ub)), -1.0, 1.0));
    // The fabric wraps round the tip: mouth -> tip -> mouth turns clockwise on a
    // counter-clockwise outline.
    if (opening >= max_open || cross(-ua, ub) >= 0) continue;
    double la = edge_length_mm(in), lb = edge_length_mm(out);
    if (std::abs(la - lb) > kDartLegLengthTolerance * std::max(la, lb)) continue;
    piece.darts.push_back(Dart{"dart" + std::to_string(piece.darts.size() + 1), a, b});
    used[a] = used[b] = true;
    ++added;
  }
  return added;
}

}  // namespace tp::geometry
