// geometry/nesting/internal/shape_prep.cpp: cleaning, growing (CGAL Minkowski sum) and outward
// simplification of item outlines.
#include "geometry/nesting/internal/shape_prep.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace tp::geometry::nesting {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

// Relative size under which two vertices count as one and three as collinear (fractions of the
// outline's bounding-box diagonal, and of its square).
constexpr double kDuplicateVertexRel = 1e-12;
constexpr double kCollinearRel = 1e-14;
/// The inflating disc is this much (relative) larger, so rounding never leaves the growth short of r.
constexpr double kInflateRadiusRel = 1e-12;

double diagonal(const Polygon& p) {
  Box2 b = bounds(p);
  return std::hypot(b.width(), b.height());
}

// Drops repeated vertices and vertices on the straight line between their neighbours.
Polygon drop_degenerate(const Polygon& in, double diag) {
  Polygon p;
  const double dup = kDuplicateVertexRel * diag;
  for (Vec2 v : in) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return {};
    if (p.empty() || norm(v - p.back()) > dup) p.push_back(v);
  }
  while (p.size() > 1 && norm(p.front() - p.back()) <= dup) p.pop_back();
  const double col = kCollinearRel * diag * diag;
  bool changed = true;
  while (changed && p.size() >= 3) {
    changed = false;
    for (size_t i = 0; i < p.size() && p.size() >= 3; ++i) {
      Vec2 a = p[(i + p.size() - 1) % p.size()], b = p[i], c = p[(i + 1) % p.size()];
      // Collinear and pointing the same way (a spike back along the edge is left for the
      // simplicity check to reject).
      if (std::fabs(cross(b - a, c - b)) <= col && dot(b - a, c - b) >= 0) {
        p.erase(p.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        --i;
      }
    }
  }
  return p;
}

Epick::Point_2 epick(Vec2 v) { return {v.x, v.y}; }

// One pending outward simplification step at a vertex.
struct Candidate {
  enum Kind { kNone, kRemoveVertex, kMiterEdge } kind = kNone;
  double cost = std::numeric_limits<double>::infinity();
  Vec2 meet;  // kMiterEdge: where the neighbouring edges meet
};

class OutwardSimplifier {
 public:
  explicit OutwardSimplifier(const Polygon& p) : v_(p), alive_(p.size(), true), next_(p.size()), prev_(p.size()) {
    const size_t n = p.size();
    for (size_t i = 0; i < n; ++i) {
      next_[i] = (i + 1) % n;
      prev_[i] = (i + n - 1) % n;
    }
    count_ = n;
    cand_.resize(n);
    for (size_t i = 0; i < n; ++i) evaluate(i);
  }

  Polygon run(double budget) {
    double spent = 0;
    while (count_ > 3) {
      size_t best = v_.size();
      for (size_t i = 0; i < v_.size(); ++i)
        if (alive_[i] && cand_[i].kind != Candidate::kNone &&
            (best == v_.size() || cand_[i].cost < cand_[best].cost))
          best = i;
      const double cost = best == v_.size() ? 0.0 : cand_[best].cost;
      if (best == v_.size() || spent + cost > budget) break;
      if (!apply(best)) {
        cand_[best] = {};  // blocked: it would make the outline cross itself
        continue;
      }
      spent += cost;
    }
    Polygon out;
    size_t start = 0;
    while (!alive_[start]) ++start;
    size_t i = start;
    do {
      out.push_back(v_[i]);
      i = next_[i];
    } while (i != start);
    return out;
  }

 private:
  void evaluate(size_t i) {
    Candidate c;
    const size_t a = prev_[i], b = next_[i], bb = next_[b];
    const Vec2 pa = v_[a], pi = v_[i], pb = v_[b], pbb = v_[bb];
    const double turn = cross(pi - pa, pb - pi);
    if (turn <= 0) {
      // Reflex (or straight) corner: cutting it off adds the triangle outside it.
      c.kind = Candidate::kRemoveVertex;
      c.cost = 0.5 * std::fabs(cross(pi - pa, pb - pa));
    } else if (cross(pb - pi, pbb - pb) > 0 && count_ > 3) {
      // Two convex corners: extend the edges on either side until they meet.
      const Vec2 d1 = pi - pa, d2 = pb - pbb;
      const double den = cross(d1, d2);
      if (std::fabs(den) > 0) {
        const double s = cross(pb - pi, d2) / den;
        const double u = cross(pb - pi, d1) / den;
        if (s > 0 && u > 0 && std::isfinite(s) && std::isfinite(u)) {
          c.kind = Candidate::kMiterEdge;
          c.meet = pi + d1 * s;
          c.cost = 0.5 * std::fabs(cross(pb - pi, c.meet - pi));
        }
      }
    }
    cand_[i] = c;
  }

  // True when segment (p, q) crosses or touches an edge of the outline other than the ones that
  // start or end at the vertices in `skip`.
  bool hits(Vec2 p, Vec2 q, const size_t* skip, size_t n_skip) const {
    const Epick::Segment_2 s(epick(p), epick(q));
    for (size_t i = 0; i < v_.size(); ++i) {
      if (!alive_[i]) continue;
      const size_t j = next_[i];
      bool skipped = false;
      for (size_t k = 0; k < n_skip; ++k) skipped |= (i == skip[k] || j == skip[k]);
      if (skipped) continue;
      if (CGAL::do_intersect(s, Epick::Segment_2(epick(v_[i]), epick(v_[j])))) return true;
    }
    return false;
  }

  bool apply(size_t i) {
    const Candidate c = cand_[i];
    const size_t a = prev_[i], b = next_[i];
    if (c.kind == Candidate::kRemoveVertex) {
      const size_t skip[] = {a, i, b};
      if (hits(v_[a], v_[b], skip, 3)) return false;
      alive_[i] = false;
      next_[a] = b;
      prev_[b] = a;
      --count_;
      refresh_around(a);
      return true;
    }
    const size_t bb = next_[b];
    const size_t skip[] = {a, i, b, bb};
    if (hits(v_[a], c.meet, skip, 4) || hits(c.meet, v_[bb], skip, 4)) return false;
    v_[i] = c.meet;
    alive_[b] = false;
    next_[i] = bb;
    prev_[bb] = i;
    --count_;
    refresh_around(i);
    return true;
  }

  void refresh_around(size_t i) {
    size_t k = i;
    for (int s = 0; s < 2; ++s) k = prev_[k];
    for (int s = 0; s < 5; ++s, k = next_[k]) evaluate(k);
  }

  std::vector<Vec2> v_;
  std::vector<bool> alive_;
  std::vector<size_t> next_, prev_;
  std::vector<Candidate> cand_;
  size_t count_ = 0;
};

}  // namespace

Result<Polygon> clean_polygon(const Polygon& outline, std::string_view what) {
  const std::string name(what);
  if (outline.size() < 3) return fail(ErrorCode::kInvalidPattern, name + ": outline has fewer than 3 vertices");
  for (Vec2 v : outline)
    if (!std::isfinite(v.x) || !std::isfinite(v.y))
      return fail(ErrorCode::kInvalidPattern, name + ": outline has a non-finite coordinate");
  Polygon p = drop_degenerate(outline, diagonal(outline));
  if (p.size() < 3) return fail(ErrorCode::kInvalidPattern, name + ": outline has no area (fewer than 3 distinct corners)");
  if (signed_area(p) < 0) std::reverse(p.begin(), p.end());
  std::vector<Epick::Point_2> pts;
  pts.reserve(p.size());
  for (Vec2 v : p) pts.push_back(epick(v));
  if (!CGAL::is_simple_2(pts.begin(), pts.end(), Epick()))
    return fail(ErrorCode::kInvalidPattern, name + ": outline crosses itself (not a simple polygon)");
  if (!(signed_area(p) > 0)) return fail(ErrorCode::kInvalidPattern, name + ": outline has zero area");
  return p;
}

Polygon inflate_polygon(const Polygon& ccw, double radius_mm, int segments) {
  segments = std::max(segments, 3);
  CGAL::Polygon_2<Epeck> a, disc;
  for (Vec2 v : ccw) a.push_back(Epeck::Point_2(v.x, v.y));
  // Circumscribing the disc (vertices at r / cos(pi/k)) keeps the growth at least r everywhere.
  const double rv = radius_mm / std::cos(std::numbers::pi / segments) * (1.0 + kInflateRadiusRel);
  for (int k = 0; k < segments; ++k) {
    const double ang = 2.0 * std::numbers::pi * (k + 0.5) / segments;
    disc.push_back(Epeck::Point_2(rv * std::cos(ang), rv * std::sin(ang)));
  }
  const auto sum = CGAL::minkowski_sum_2(a, disc);
  Polygon out;
  for (auto it = sum.outer_boundary().vertices_begin(); it != sum.outer_boundary().vertices_end(); ++it)
    out.push_back({CGAL::to_double(it->x()), CGAL::to_double(it->y())});
  if (signed_area(out) < 0) std::reverse(out.begin(), out.end());
  Polygon cleaned = drop_degenerate(out, diagonal(out));
  return cleaned.size() >= 3 ? cleaned : out;
}

Polygon simplify_outward(const Polygon& ccw, double max_added_area_mm2) {
  if (ccw.size() <= 3) return ccw;
  OutwardSimplifier s(ccw);
  return s.run(std::max(0.0, max_added_area_mm2));
}

}  // namespace tp::geometry::nesting
