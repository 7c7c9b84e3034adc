// geometry/allowance/cut_outline.cpp: per-edge offset regions and corner regions, united exactly.
#include "geometry/allowance/cut_outline.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using CPolygon = CGAL::Polygon_2<K>;
using CPolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

// Segments shorter than this carry no direction and are dropped.
constexpr double kMinSegment_mm = 1e-6;
// Output vertices whose turn moves the outline less than this are collinear and dropped.
constexpr double kCollinear_mm = 1e-5;

Vec2 outward_normal(Vec2 dir) { return {dir.y, -dir.x}; }  // right of travel: outside of a CCW piece

// Adds a region given as points in any orientation; degenerate or self-intersecting ones are skipped.
void add_region(std::vector<CPolygon>& out, std::initializer_list<Vec2> pts) {
  CPolygon poly;
  for (Vec2 p : pts) {
    K::Point_2 q(p.x, p.y);
    if (poly.size() > 0 && (poly.container().back() == q)) continue;
    poly.push_back(q);
  }
  while (poly.size() > 1 && poly.container().front() == poly.container().back()) poly.container().pop_back();
  if (poly.size() < 3 || !poly.is_simple()) return;
  const auto orient = poly.orientation();
  if (orient == CGAL::COLLINEAR) return;
  if (orient == CGAL::CLOCKWISE) poly.reverse_orientation();
  out.push_back(std::move(poly));
}

// Intersection of lines p + t*d and q + s*e; none when parallel.
std::optional<Vec2> line_intersection(Vec2 p, Vec2 d, Vec2 q, Vec2 e) {
  const double den = cross(d, e);
  if (std::abs(den) < kParallelDeterminant) return std::nullopt;
  const double t = cross(q - p, e) / den;
  return p + d * t;
}

// Reflects point x across the line through c with unit direction d.
Vec2 reflect(Vec2 x, Vec2 c, Vec2 d) {
  const Vec2 v = x - c;
  return c + d * (2 * dot(v, d)) - v;
}

struct CleanEdge {
  std::vector<Vec2> pts;  // consecutive duplicates removed
  Vec2 first_dir, last_dir;
};

void edge_regions(const CleanEdge& e, double w, double mitre_limit, std::vector<CPolygon>& out) {
  if (w <= 0) return;
  for (size_t j = 0; j + 1 < e.pts.size(); ++j) {
    const Vec2 a = e.pts[j], b = e.pts[j + 1];
    const Vec2 n = outward_normal(normalized(b - a));
    add_region(out, {a, b, b + n * w, a + n * w});
    if (j + 2 >= e.pts.size()) continue;
    // Join with the next segment where the offsets open a gap (outward bend).
    const Vec2 n2 = outward_normal(normalized(e.pts[j + 2] - b));
    if (cross(b - a, e.pts[j + 2] - b) <= 0) continue;
    const Vec2 bis = n + n2;
    const double c2 = dot(bis, bis);
    const double factor = c2 > 0 ? 2.0 / c2 : 1e9;  // |mitre|^2 / w^2 = 1 / cos^2(half angle)
    if (std::sqrt(factor) <= mitre_limit) add_region(out, {b, b + n * w, b + bis * (w * factor), b + n2 * w});
    else add_region(out, {b, b + n * w, b + n2 * w});
  }
}

void corner_region(Vec2 c, Vec2 din, Vec2 dout, double win, double wout, CornerStyle style, double mitre_limit,
                   std::vector<CPolygon>& out) {
  if (win <= 0 && wout <= 0) return;
  const Vec2 nin = outward_normal(din), nout = outward_normal(dout);
  const double turn = cross(din, dout);
  // Concave corners: the edges' own quads overlap and their offset lines meet in the union.
  if (turn <= 0 && dot(din, dout) > 0) return;
  const double wmax = std::max(win, wout);
  switch (style) {
    case CornerStyle::kMitre: {
      const auto x = line_intersection(c + nin * win, din, c + nout * wout, dout);
      if (x && norm(*x - c) <= mitre_limit * wmax) add_region(out, {c, c + nin * win, *x, c + nout * wout});
      else add_region(out, {c, c + nin * win, c + nout * wout});
      return;
    }
    case CornerStyle::kSquare: {
      // Each allowance runs on past the corner by the other edge's width and ends square.
      add_region(out, {c, c + nin * win, c + nin * win + din * wout, c + din * wout});
      add_region(out, {c, c - dout * win, c - dout * win + nout * wout, c + nout * wout});
      // Acute corners leave a notch between the two far corners: close it.
      add_region(out, {c, c + nin * win + din * wout, c + nout * wout - dout * win});
      return;
    }
    case CornerStyle::kReflectIncoming:
    case CornerStyle::kReflectOutgoing: {
      // The folded edge's allowance ends on the mirror (across its seam line) of the other cut line.
      const bool incoming = style == CornerStyle::kReflectIncoming;
      const Vec2 axis = incoming ? din : dout;               // seam line folded along
      const Vec2 nf = incoming ? nin : nout;
      const double wf = incoming ? win : wout;
      const Vec2 other_pt = incoming ? c + nout * wout : c + nin * win;
      const Vec2 other_dir = incoming ? dout : din;
      const Vec2 rp = reflect(other_pt, c, axis);
      const Vec2 rd = reflect(c + other_dir, c, axis) - c;
      const auto a = line_intersection(c, axis, rp, rd);
      const auto b = line_intersection(c + nf * wf, axis, rp, rd);
      // Away from the corner along the folded edge: forward for the incoming edge, back for the outgoing.
      const double sign = incoming ? 1.0 : -1.0;
      if (a && b && dot(*a - c, axis) * sign >= 0 && dot(*b - (c + nf * wf), axis) * sign >= 0 &&
          norm(*b - c) <= mitre_limit * (wmax + wf) + wmax) {
        add_region(out, {c, c + nf * wf, *b, *a});
        // Between the mirrored end and the other edge's own allowance.
        add_region(out, {c, *a, other_pt});
      } else {
        corner_region(c, din, dout, win, wout, CornerStyle::kMitre, mitre_limit, out);
      }
      return;
    }
  }
}

Result<CleanEdge> clean_edge(const std::vector<Vec2>& pts, size_t k) {
  CleanEdge e;
  for (Vec2 p : pts) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      return fail(ErrorCode::kInvalidArgument, "edge " + std::to_string(k) + " has a non-finite point");
    if (!e.pts.empty() && norm(p - e.pts.back()) < kMinSegment_mm) continue;
    e.pts.push_back(p);
  }
  if (e.pts.size() < 2) return e;
  e.first_dir = normalized(e.pts[1] - e.pts[0]);
  e.last_dir = normalized(e.pts.back() - e.pts[e.pts.size() - 2]);
  return e;
}

Polygon simplify(const Polygon& in) {
  Polygon out = in;
  bool changed = true;
  while (changed && out.size() > 3) {
    changed = false;
    Polygon next;
    for (size_t i = 0; i < out.size(); ++i) {
      const Vec2 p = out[(i + out.size() - 1) % out.size()], c = out[i], n = out[(i + 1) % out.size()];
      const double len = norm(n - p);
      const double dev = len > 0 ? std::abs(cross(n - p, c - p)) / len : norm(c - p);
      if (dev < kCollinear_mm && dot(c - p, n - c) >= 0 && out.size() - (i - next.size()) > 3) {
        changed = true;
        continue;
      }
      next.push_back(c);
    }
    out = std::move(next);
  }
  return out;
}

}  // namespace

Result<Polygon> cut_outline(const std::vector<std::vector<Vec2>>& edges, const std::vector<double>& width_mm,
                           const std::vector<CornerStyle>& corner, double mitre_limit, const Polygon* extra) {
  const size_t n = edges.size();
  if (n == 0) return fail(ErrorCode::kAllowance, "cut outline: no edges");
  if (width_mm.size() != n || corner.size() != n)
    return fail(ErrorCode::kAllowance, "cut outline: " + std::to_string(n) + " edges but " + std::to_string(width_mm.size()) +
                                           " widths and " + std::to_string(corner.size()) + " corner styles");
  std::vector<CleanEdge> clean;
  Polygon seam;
  for (size_t k = 0; k < n; ++k) {
    if (!std::isfinite(width_mm[k]) || width_mm[k] < 0)
      return fail(ErrorCode::kAllowance, "cut outline: edge " + std::to_string(k) + " width must be >= 0 mm");
    auto e = clean_edge(edges[k], k);
    if (!e) return std::unexpected(e.error().with_context("cut outline"));
    for (size_t i = 0; i + 1 < e->pts.size(); ++i)
      if (seam.empty() || norm(e->pts[i] - seam.back()) >= kMinSegment_mm) seam.push_back(e->pts[i]);
    clean.push_back(std::move(*e));
  }
  while (seam.size() > 1 && norm(seam.front() - seam.back()) < kMinSegment_mm) seam.pop_back();
  if (seam.size() < 3) return fail(ErrorCode::kAllowance, "cut outline: the seam line has fewer than 3 distinct points");
  if (signed_area(seam) <= 0) return fail(ErrorCode::kAllowance, "cut outline: the seam line is not counter-clockwise");

  std::vector<CPolygon> regions;
  {
    CPolygon base;
    for (Vec2 p : seam) base.push_back(K::Point_2(p.x, p.y));
    if (!base.is_simple()) return fail(ErrorCode::kAllowance, "cut outline: the seam line crosses itself");
    regions.push_back(base);
  }
  for (size_t k = 0; k < n; ++k) edge_regions(clean[k], width_mm[k], mitre_limit, regions);
  for (size_t k = 0; k < n; ++k) {
    const CleanEdge& a = clean[k];
    const CleanEdge& b = clean[(k + 1) % n];
    if (a.pts.size() < 2 || b.pts.size() < 2) continue;
    corner_region(a.pts.back(), a.last_dir, b.first_dir, width_mm[k], width_mm[(k + 1) % n], corner[k], mitre_limit,
                  regions);
  }
  if (extra && extra->size() >= 3) {
    std::vector<CPolygon> tmp;
    CPolygon e;
    for (Vec2 p : *extra) e.push_back(K::Point_2(p.x, p.y));
    if (e.is_simple()) {
      if (e.orientation() == CGAL::CLOCKWISE) e.reverse_orientation();
      regions.push_back(e);
    }
  }

  CGAL::Polygon_set_2<K> set;
  set.join(regions.begin(), regions.end());
  std::vector<CPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  if (parts.empty()) return fail(ErrorCode::kAllowance, "cut outline: the union is empty");
  // All regions touch the seam line, so the union is one piece; keep the largest to be safe.
  size_t best = 0;
  double best_area = -1;
  for (size_t i = 0; i < parts.size(); ++i) {
    const double a = CGAL::to_double(parts[i].outer_boundary().area());
    if (a > best_area) best_area = a, best = i;
  }
  Polygon outline;
  for (auto it = parts[best].outer_boundary().vertices_begin(); it != parts[best].outer_boundary().vertices_end(); ++it)
    outline.push_back({CGAL::to_double(it->x()), CGAL::to_double(it->y())});
  if (signed_area(outline) < 0) std::reverse(outline.begin(), outline.end());
  return simplify(outline);
}

Result<Polygon> cut_outline(const Piece& piece, const PieceAllowance& allowance, double mitre_limit) {
  std::vector<std::vector<Vec2>> edges;
  for (const Edge& e : piece.edges) edges.push_back(e.points_mm);
  auto r = cut_outline(edges, allowance.width_mm, allowance.corner, mitre_limit);
  if (!r) return std::unexpected(r.error().with_context("piece '" + piece.name + "'"));
  return r;
}

}  // namespace tp::geometry
