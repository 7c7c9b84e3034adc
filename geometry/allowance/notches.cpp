// geometry/allowance/notches.cpp: notch positions along edges and their cut shapes.
#include "geometry/allowance/notches.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

// Stitch ends this close to an edge's end are at a corner, which marks itself.
constexpr double kCornerSlack_mm = 1.0;
// Notches closer than this on one edge are the same notch.
constexpr double kSameNotch_mm = 2.0;
// Without allowance a notch cuts this far into the piece at most.
constexpr double kNoAllowanceDepth_mm = 3.0;

// First crossing of the ray p + t d (t >= 0) with the polygon, or p when none.
Vec2 ray_hit(const Polygon& poly, Vec2 p, Vec2 d) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const Vec2 e = b - a;
    const double den = cross(d, e);
    if (std::abs(den) < kParallelDeterminant) continue;
    const double t = cross(a - p, e) / den;
    const double u = cross(a - p, d) / den;
    if (t >= -kBoundarySlack && u >= -kBoundarySlack && u <= 1 + kBoundarySlack)
      best = std::min(best, std::max(0.0, t));
  }
  return std::isfinite(best) ? p + d * best : p;
}

std::vector<std::vector<Vec2>> shape(NotchType type, Vec2 c, Vec2 in, Vec2 along, double depth, double width) {
  const Vec2 tip = c + in * depth;
  const Vec2 half = along * (0.5 * width);
  switch (type) {
    case NotchType::kSlit: return {{c, tip}};
    case NotchType::kV: return {{c - half, tip, c + half}};
    case NotchType::kT: return {{c, tip}, {tip - half, tip + half}};
    case NotchType::kU: return {{c - half, tip - half, tip + half, c + half}};
  }
  return {{c, tip}};
}

}  // namespace

std::vector<NotchCut> piece_notches(const Pattern& pattern, int piece, const PieceAllowance& allowance,
                                    const Polygon& cut, const Finishing& f) {
  const Piece& pc = pattern.pieces[static_cast<size_t>(piece)];
  struct Want {
    std::string name;
    int edge;
    double s;
    NotchType type;
  };
  std::vector<Want> wants;
  for (const Notch& n : pc.notches) wants.push_back({n.name, n.edge, n.position_mm, n.type});
  for (const Stitch& st : pattern.stitches) {
    for (const EdgeSpan* sp : {&st.a, &st.b}) {
      if (sp->piece != piece || sp->edge < 0 || static_cast<size_t>(sp->edge) >= pc.edges.size()) continue;
      const double len = edge_length_mm(pc.edges[static_cast<size_t>(sp->edge)]);
      const auto r = span_range_mm(pattern, *sp);
      if (f.notch_stitch_ends)
        for (double s : {r[0], r[1]})
          if (s > kCornerSlack_mm && s < len - kCornerSlack_mm) wants.push_back({"stitch_end", sp->edge, s, f.stitch_notch_type});
      // A balance notch at the middle of a long span, unless the pattern notches it already.
      if (r[1] - r[0] > kBalanceNotchSpan_mm) {
        bool notched = false;
        for (const Notch& n : pc.notches)
          notched |= n.edge == sp->edge && n.position_mm > r[0] + kCornerSlack_mm && n.position_mm < r[1] - kCornerSlack_mm;
        // Mid-span on both sides of the stitch: the same arc-length fraction meets when sewn.
        if (!notched) wants.push_back({"balance", sp->edge, 0.5 * (r[0] + r[1]), f.stitch_notch_type});
      }
    }
  }
  std::vector<NotchCut> out;
  for (const Want& w : wants) {
    if (w.edge < 0 || static_cast<size_t>(w.edge) >= pc.edges.size()) continue;
    bool duplicate = false;
    for (const NotchCut& n : out) duplicate |= n.edge == w.edge && std::abs(n.position_mm - w.s) < kSameNotch_mm;
    if (duplicate) continue;
    const Edge& e = pc.edges[static_cast<size_t>(w.edge)];
    NotchCut n;
    n.name = w.name;
    n.edge = w.edge;
    n.position_mm = w.s;
    n.type = w.type;
    n.seam_point_mm = point_along_edge(e, w.s);
    const Vec2 t = tangent_along_edge(e, w.s);
    const Vec2 outward{t.y, -t.x};
    n.inward = -outward;
    const double width = allowance.width_mm[static_cast<size_t>(w.edge)];
    n.cut_point_mm = width > 0 ? ray_hit(cut, n.seam_point_mm, outward) : n.seam_point_mm;
    n.depth_mm = width > 0 ? std::min(f.notch_depth_mm, 0.6 * norm(n.cut_point_mm - n.seam_point_mm))
                           : std::min(f.notch_depth_mm, kNoAllowanceDepth_mm);
    n.strokes = shape(n.type, n.cut_point_mm, n.inward, t, n.depth_mm, f.notch_width_mm);
    out.push_back(std::move(n));
  }
  std::sort(out.begin(), out.end(), [](const NotchCut& a, const NotchCut& b) {
    return a.edge != b.edge ? a.edge < b.edge : a.position_mm < b.position_mm;
  });
  return out;
}

}  // namespace tp::geometry
