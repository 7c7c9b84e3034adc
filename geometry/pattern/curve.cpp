// geometry/pattern/curve.cpp: flattening Bezier chains and arcs, and exact edge reversal/joining.
#include "geometry/pattern/curve.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/common/segment.h"
#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

/// Deepest subdivision of one Bezier segment (2^16 pieces), a guard against hostile input.
constexpr int kMaxBezierDepth = 16;
/// Points closer than this relative to the figure size are the same point when joining arcs.
constexpr double kSameCircleRelTolerance = 1e-6;

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

/// Appends the points of cubic a,b,c,d after a (adaptive de Casteljau subdivision).
Status flatten_cubic(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double tol, int depth, std::vector<Vec2>& out) {
  // The curve lies in the hull of its controls: flat enough when both inner controls are near a-d.
  if (depth >= kMaxBezierDepth ||
      std::max(distance_to_segment(b, a, d), distance_to_segment(c, a, d)) <= tol) {
    if (out.size() >= kMaxEdgePoints)
      return fail(ErrorCode::kInvalidPattern, "curve needs more than " + std::to_string(kMaxEdgePoints) + " points");
    out.push_back(d);
    return {};
  }
  Vec2 ab = (a + b) * 0.5, bc = (b + c) * 0.5, cd = (c + d) * 0.5;
  Vec2 abc = (ab + bc) * 0.5, bcd = (bc + cd) * 0.5, m = (abc + bcd) * 0.5;
  Status s = flatten_cubic(a, ab, abc, m, tol, depth + 1, out);
  if (!s) return s;
  return flatten_cubic(m, bcd, cd, d, tol, depth + 1, out);
}

/// Sweep of an arc from `a` through `m` to `b` around `c`: signed angle, > 0 counter-clockwise.
double arc_sweep(Vec2 c, Vec2 a, Vec2 m, Vec2 b) {
  double ta = std::atan2(a.y - c.y, a.x - c.x);
  auto ccw_from_a = [&](Vec2 p) {
    double t = std::atan2(p.y - c.y, p.x - c.x) - ta;
    while (t < 0) t += 2 * std::numbers::pi;
    while (t >= 2 * std::numbers::pi) t -= 2 * std::numbers::pi;
    return t;
  };
  double tb = ccw_from_a(b), tm = ccw_from_a(m);
  if (tb <= 0) tb = 2 * std::numbers::pi;  // a closed circle is not an edge; treat a==b as a full turn
  return tm < tb ? tb : -(2 * std::numbers::pi - tb);
}

Status flatten_arc(Vec2 a, Vec2 b, Vec2 centre, Vec2 mid, double tol, std::vector<Vec2>& out) {
  double ra = norm(a - centre), rb = norm(b - centre);
  double r = std::max(ra, rb);
  if (!(r > 0)) return fail(ErrorCode::kInvalidPattern, "arc has zero radius");
  double sweep = arc_sweep(centre, a, mid, b);
  // Segment angle so that the sagitta r(1-cos(step/2)) stays within the tolerance.
  double step = 2 * std::acos(std::clamp(1 - tol / r, -1.0, 1.0));
  double n_real = std::ceil(std::abs(sweep) / std::max(step, kMinDivisor));
  if (!(n_real < static_cast<double>(kMaxEdgePoints)))
    return fail(ErrorCode::kInvalidPattern, "arc needs more than " + std::to_string(kMaxEdgePoints) + " points");
  int n = std::max(1, static_cast<int>(n_real));
  double t0 = std::atan2(a.y - centre.y, a.x - centre.x);
  // The radius is blended from start to end so both ends are hit exactly even if slightly unequal.
  for (int i = 1; i < n; ++i) {
    double f = static_cast<double>(i) / n;
    double t = t0 + sweep * f;
    double rr = ra + (rb - ra) * f;
    out.push_back(centre + Vec2{std::cos(t), std::sin(t)} * rr);
  }
  out.push_back(b);
  return {};
}

}  // namespace

Status flatten_edge(Edge& edge, Vec2 start_mm, Vec2 end_mm, double chord_tolerance_mm) {
  if (!finite(start_mm) || !finite(end_mm))
    return fail(ErrorCode::kInvalidPattern, "edge '" + edge.name + "' has a non-finite end point");
  for (Vec2 c : edge.control_mm)
    if (!finite(c)) return fail(ErrorCode::kInvalidPattern, "edge '" + edge.name + "' has a non-finite control point");
  double tol = std::max(chord_tolerance_mm, kMinChordTolerance_mm);
  auto bad_count = [&](const char* what) {
    return fail(ErrorCode::kInvalidPattern, "edge '" + edge.name + "': " + what + ", got " +
                                                std::to_string(edge.control_mm.size()) + " control points");
  };
  std::vector<Vec2> out{start_mm};
  const auto& cp = edge.control_mm;
  switch (edge.curve) {
    case EdgeCurve::kLine:
      out.push_back(end_mm);
      break;
    case EdgeCurve::kPolyline: {
      for (size_t i = 1; i + 1 < edge.points_mm.size(); ++i) {
        if (!finite(edge.points_mm[i]))
          return fail(ErrorCode::kInvalidPattern, "edge '" + edge.name + "' has a non-finite point");
        out.push_back(edge.points_mm[i]);
      }
      out.push_back(end_mm);
      break;
    }
    case EdgeCurve::kQuadratic: {
      if (cp.size() % 2 != 1) return bad_count("a quadratic chain needs 2n-1 control points");
      Vec2 p0 = start_mm;
      for (size_t i = 0; i < cp.size(); i += 2) {
        Vec2 p2 = i + 1 < cp.size() ? cp[i + 1] : end_mm;
        // Degree elevation: the quadratic p0,q,p2 is the cubic p0, p0+2/3(q-p0), p2+2/3(q-p2), p2.
        Vec2 q = cp[i];
        Status s = flatten_cubic(p0, p0 + (q - p0) * (2.0 / 3.0), p2 + (q - p2) * (2.0 / 3.0), p2, tol, 0, out);
        if (!s) return std::unexpected(s.error().with_context("edge '" + edge.name + "'"));
        p0 = p2;
      }
      break;
    }
    case EdgeCurve::kCubic: {
      if (cp.size() % 3 != 2) return bad_count("a cubic chain needs 3n-1 control points");
      Vec2 p0 = start_mm;
      for (size_t i = 0; i < cp.size(); i += 3) {
        Vec2 p3 = i + 2 < cp.size() ? cp[i + 2] : end_mm;
        Status s = flatten_cubic(p0, cp[i], cp[i + 1], p3, tol, 0, out);
        if (!s) return std::unexpected(s.error().with_context("edge '" + edge.name + "'"));
        p0 = p3;
      }
      break;
    }
    case EdgeCurve::kArc: {
      if (cp.size() != 2) return bad_count("an arc needs {centre, point on arc}");
      // The centre is recomputed from the three points so the stored one cannot disagree.
      auto c = circle_centre(start_mm, cp[1], end_mm);
      if (!c) return fail(ErrorCode::kInvalidPattern, "edge '" + edge.name + "': arc point is collinear with its ends");
      edge.control_mm[0] = *c;
      Status s = flatten_arc(start_mm, end_mm, *c, cp[1], tol, out);
      if (!s) return std::unexpected(s.error().with_context("edge '" + edge.name + "'"));
      break;
    }
  }
  edge.points_mm = std::move(out);
  return {};
}

Edge make_line_edge(std::string name, Vec2 a_mm, Vec2 b_mm) {
  return Edge{std::move(name), EdgeCurve::kLine, {}, {a_mm, b_mm}};
}

std::optional<Vec2> circle_centre(Vec2 a, Vec2 b, Vec2 c) {
  // Perpendicular bisectors intersect at the centre; relative to a to keep precision.
  Vec2 ab = b - a, ac = c - a;
  double d = 2 * cross(ab, ac);
  double scale = std::max(dot(ab, ab), dot(ac, ac));
  if (!(std::abs(d) > kParallelDeterminant * scale) || !std::isfinite(d)) return std::nullopt;
  double ab2 = dot(ab, ab), ac2 = dot(ac, ac);
  Vec2 rel{(ac.y * ab2 - ab.y * ac2) / d, (ab.x * ac2 - ac.x * ab2) / d};
  Vec2 centre = a + rel;
  if (!finite(centre)) return std::nullopt;
  return centre;
}

Edge reversed_edge(const Edge& edge) {
  Edge r = edge;
  std::reverse(r.points_mm.begin(), r.points_mm.end());
  // Bezier chains are laid out symmetrically, so reversing the list reverses the chain; an arc's
  // centre and point-on-arc stay valid.
  if (edge.curve == EdgeCurve::kQuadratic || edge.curve == EdgeCurve::kCubic)
    std::reverse(r.control_mm.begin(), r.control_mm.end());
  return r;
}

Edge transformed_edge(const Edge& edge, const Affine2& map) {
  Edge r = edge;
  for (Vec2& p : r.points_mm) p = map.apply(p);
  for (Vec2& p : r.control_mm) p = map.apply(p);
  return r;
}

std::optional<std::vector<Vec2>> as_cubic_chain(const Edge& edge) {
  if (edge.points_mm.size() < 2) return std::nullopt;
  Vec2 a = edge.points_mm.front(), b = edge.points_mm.back();
  switch (edge.curve) {
    case EdgeCurve::kLine:
      return std::vector<Vec2>{a + (b - a) / 3.0, a + (b - a) * (2.0 / 3.0)};
    case EdgeCurve::kCubic:
      return edge.control_mm;
    case EdgeCurve::kQuadratic: {
      std::vector<Vec2> out;
      Vec2 p0 = a;
      for (size_t i = 0; i < edge.control_mm.size(); i += 2) {
        Vec2 q = edge.control_mm[i];
        Vec2 p2 = i + 1 < edge.control_mm.size() ? edge.control_mm[i + 1] : b;
        out.push_back(p0 + (q - p0) * (2.0 / 3.0));
        out.push_back(p2 + (q - p2) * (2.0 / 3.0));
        if (i + 1 < edge.control_mm.size()) out.push_back(p2);
        p0 = p2;
      }
      return out;
    }
    case EdgeCurve::kArc:
    case EdgeCurve::kPolyline:
      return std::nullopt;
  }
  return std::nullopt;
}

Edge joined_edges(const Edge& a, const Edge& b) {
  Edge r;
  r.name = a.name;
  r.points_mm = a.points_mm;
  if (!b.points_mm.empty()) r.points_mm.insert(r.points_mm.end(), b.points_mm.begin() + 1, b.points_mm.end());
  if (a.points_mm.size() < 2 || b.points_mm.size() < 2) {
    r.curve = EdgeCurve::kPolyline;
    return r;
  }
  Vec2 s = a.points_mm.front(), j = a.points_mm.back(), e = b.points_mm.back();
  double size = std::max({norm(j - s), norm(e - j), kMinDivisor});
  // Two collinear lines pointing the same way stay one line.
  if (a.curve == EdgeCurve::kLine && b.curve == EdgeCurve::kLine &&
      std::abs(cross(j - s, e - j)) <= kSameCircleRelTolerance * size * size && dot(j - s, e - j) > 0) {
    r.curve = EdgeCurve::kLine;
    r.points_mm = {s, e};
    return r;
  }
  // Two arcs of one circle turning the same way: one arc through the joint.
  if (a.curve == EdgeCurve::kArc && b.curve == EdgeCurve::kArc && a.control_mm.size() == 2 &&
      b.control_mm.size() == 2 && norm(a.control_mm[0] - b.control_mm[0]) <= kSameCircleRelTolerance * size &&
      arc_sweep(a.control_mm[0], s, a.control_mm[1], j) * arc_sweep(b.control_mm[0], j, b.control_mm[1], e) > 0) {
    double total = std::abs(arc_sweep(a.control_mm[0], s, a.control_mm[1], j)) +
                   std::abs(arc_sweep(b.control_mm[0], j, b.control_mm[1], e));
    if (total < 2 * std::numbers::pi - 1e-6) {
      r.curve = EdgeCurve::kArc;
      r.control_mm = {a.control_mm[0], j};
      return r;
    }
  }
  // Bezier chains (lines and quadratics raised to cubics) join into one cubic chain.
  if (a.curve != EdgeCurve::kArc && a.curve != EdgeCurve::kPolyline && b.curve != EdgeCurve::kArc &&
      b.curve != EdgeCurve::kPolyline) {
    if (a.curve == EdgeCurve::kQuadratic && b.curve == EdgeCurve::kQuadratic) {
      r.curve = EdgeCurve::kQuadratic;
      r.control_mm = a.control_mm;
      r.control_mm.push_back(j);
      r.control_mm.insert(r.control_mm.end(), b.control_mm.begin(), b.control_mm.end());
      return r;
    }
    auto ca = as_cubic_chain(a), cb = as_cubic_chain(b);
    if (ca && cb) {
      r.curve = EdgeCurve::kCubic;
      r.control_mm = *ca;
      r.control_mm.push_back(j);
      r.control_mm.insert(r.control_mm.end(), cb->begin(), cb->end());
      return r;
    }
  }
  r.curve = EdgeCurve::kPolyline;
  return r;
}

}  // namespace tp::geometry
