// geometry/design/internal/allowance_source.cpp: inverse of the mitred offset map (Appendix A's
// quads), then the partner's (or own) inner point at the same seam position and depth.
#include "geometry/design/internal/allowance_source.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/common/tolerances.h"

namespace tp::geometry::internal {
namespace {

// A mitre vector never grows beyond this many unit distances (very sharp corners).
constexpr double kMaxMitre = 4.0;
// Slack on t and d when accepting a quad solution (numerical noise on shared mitre rays).
constexpr double kParamSlack = 1e-9;
/// |n0 + n1|² below this: the two normals are opposite (the outline turns back on itself), no mitre.
constexpr double kOppositeNormals = 1e-12;
/// A quadratic whose square term is below this, relative to its linear one, is solved as linear.
constexpr double kNegligibleSquareTerm = 1e-12;
// Boundary turns sharper than this are corners whose mitre the band triangles must respect.
constexpr double kSharpTurn_rad = 0.35;

Vec2 vertex_position(const GarmentSurface& s, int piece, int local) {
  return s.chart(piece).piece->mesh.vertices_mm[static_cast<size_t>(local)];
}

}  // namespace

AllowanceSource::AllowanceSource(const GarmentSurface& surface) : surface_(surface) {
  mitre_.resize(static_cast<size_t>(surface.piece_count()));
  for (int p = 0; p < surface.piece_count(); ++p) {
    const PieceChart& c = surface.chart(p);
    const size_t n = c.loop.size();
    auto& m = mitre_[static_cast<size_t>(p)];
    m.resize(n);
    for (size_t k = 0; k < n; ++k) {
      const Vec2 prev = vertex_position(surface, p, c.loop[(k + n - 1) % n]);
      const Vec2 cur = vertex_position(surface, p, c.loop[k]);
      const Vec2 next = vertex_position(surface, p, c.loop[(k + 1) % n]);
      const Vec2 d0 = normalized(cur - prev), d1 = normalized(next - cur);
      const Vec2 n0{d0.y, -d0.x}, n1{d1.y, -d1.x};
      Vec2 bis = n0 + n1;
      const double len2 = dot(bis, bis);
      // Mitre: along the bisector, long enough to sit at unit distance from both segments' lines.
      Vec2 mv = len2 > kOppositeNormals ? bis * (2.0 / len2) : n0;
      if (norm(mv) > kMaxMitre) mv = normalized(mv) * kMaxMitre;
      m[k] = mv;
    }
  }
}

namespace {

// Solutions (t, d) of x = p0 + t e + d (b + t c) for one quad; returns how many.
int solve_quad(Vec2 x, Vec2 p0, Vec2 e, Vec2 b, Vec2 cc, double (&t_out)[2], double (&d_out)[2]) {
  const Vec2 q = x - p0;
  const double qa = -cross(e, cc);
  const double qb = cross(q, cc) - cross(e, b);
  const double qc = cross(q, b);
  double roots[2];
  int count = 0;
  if (std::abs(qa) < kNegligibleSquareTerm * (std::abs(qb) + kNegligibleSquareTerm)) {
    if (std::abs(qb) > 0) roots[count++] = -qc / qb;
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      const double sq = std::sqrt(disc);
      // Numerically stable pair of roots.
      const double tmp = -0.5 * (qb + std::copysign(sq, qb));
      if (tmp != 0) roots[count++] = qc / tmp;
      if (qa != 0) roots[count++] = tmp / qa;
    }
  }
  int n = 0;
  for (int r = 0; r < count; ++r) {
    const Vec2 dir = b + cc * roots[r];
    const double dd = dot(dir, dir);
    if (dd <= 0) continue;
    t_out[n] = roots[r];
    d_out[n] = dot(q - e * roots[r], dir) / dd;
    ++n;
  }
  return n;
}

}  // namespace

SeamCoordinates AllowanceSource::seam_coordinates_in(int piece, int segment, Vec2 x) const {
  const PieceChart& c = surface_.chart(piece);
  const auto& m = mitre_[static_cast<size_t>(piece)];
  const size_t n = c.loop.size();
  const size_t k = static_cast<size_t>(segment);
  const Vec2 p0 = vertex_position(surface_, piece, c.loop[k]);
  const Vec2 p1 = vertex_position(surface_, piece, c.loop[(k + 1) % n]);
  double t[2], d[2];
  const int count = solve_quad(x, p0, p1 - p0, m[k], m[(k + 1) % n] - m[k], t, d);
  // The root nearest the quad (distance of t from 0..1), for points just past its mitre lines.
  SeamCoordinates best{segment, 0, 0};
  double best_off = std::numeric_limits<double>::infinity();
  for (int r = 0; r < count; ++r) {
    const double off = std::max({0.0, -t[r], t[r] - 1}) + (d[r] < 0 ? -d[r] : 0.0);
    if (off < best_off) {
      best_off = off;
      best = {segment, t[r], d[r]};
    }
  }
  if (count == 0) {
    const Vec2 e = p1 - p0;
    const double len2 = dot(e, e);
    const double tn = len2 > 0 ? dot(x - p0, e) / len2 : 0.0;
    best = {segment, tn, norm(x - (p0 + e * tn))};
  }
  return best;
}

SeamCoordinates AllowanceSource::seam_coordinates(int piece, Vec2 x) const {
  const PieceChart& c = surface_.chart(piece);
  const auto& m = mitre_[static_cast<size_t>(piece)];
  const size_t n = c.loop.size();
  SeamCoordinates best;
  double best_d = std::numeric_limits<double>::infinity();
  double best_fallback = std::numeric_limits<double>::infinity();
  SeamCoordinates fallback;
  for (size_t k = 0; k < n; ++k) {
    const Vec2 p0 = vertex_position(surface_, piece, c.loop[k]);
    const Vec2 p1 = vertex_position(surface_, piece, c.loop[(k + 1) % n]);
    const Vec2 e = p1 - p0;
    const double len2 = dot(e, e);
    if (len2 <= 0) continue;
    // Nearest point on the segment, for the fallback and to skip far segments cheaply.
    const double tn = std::clamp(dot(x - p0, e) / len2, 0.0, 1.0);
    const Vec2 off = x - (p0 + e * tn);
    const double dist2 = dot(off, off);
    if (dist2 < best_fallback) {
      best_fallback = dist2;
      fallback = {static_cast<int>(k), tn, std::sqrt(dist2)};
    }
    const double reach = best_d * kMaxMitre + kBoundarySlack;
    if (dist2 > reach * reach) continue;
    // Solve x = p0 + t e + d (b + t c) for t, d: the quad between the mitre rays at both ends.
    double ts[2], ds[2];
    const int count = solve_quad(x, p0, e, m[k], m[(k + 1) % n] - m[k], ts, ds);
    for (int r = 0; r < count; ++r) {
      const double t = ts[r], d = ds[r];
      if (t < -kParamSlack || t > 1 + kParamSlack || d < -kBoundarySlack) continue;
      if (d < best_d) {
        best_d = d;
        best = {static_cast<int>(k), std::clamp(t, 0.0, 1.0), std::max(0.0, d)};
      }
    }
  }
  return best.segment >= 0 ? best : fallback;
}

Vec2 AllowanceSource::seam_point(int piece, const SeamCoordinates& sc) const {
  const PieceChart& c = surface_.chart(piece);
  const auto& m = mitre_[static_cast<size_t>(piece)];
  const size_t n = c.loop.size();
  const size_t k = static_cast<size_t>(sc.segment);
  const Vec2 p0 = vertex_position(surface_, piece, c.loop[k]);
  const Vec2 p1 = vertex_position(surface_, piece, c.loop[(k + 1) % n]);
  const Vec2 dir = m[k] * (1 - sc.t) + m[(k + 1) % n] * sc.t;
  return p0 + (p1 - p0) * sc.t + dir * sc.d_mm;
}

AllowanceSample AllowanceSource::source(int piece, const SeamCoordinates& sc) const {
  AllowanceSample out;
  if (sc.segment < 0) return out;
  const BoundarySegment& seg = surface_.chart(piece).segments[static_cast<size_t>(sc.segment)];
  int src_piece = piece;
  SeamCoordinates src = sc;
  src.d_mm = -sc.d_mm;  // the inner strip at the same depth
  out.category = 2;
  if (seg.partner_piece >= 0) {
    src_piece = seg.partner_piece;
    src.segment = seg.partner_segment;
    src.t = seg.partner_reversed ? 1 - sc.t : sc.t;
    out.category = 1;
  }
  out.piece = src_piece;
  out.position_mm = seam_point(src_piece, src);
  // A narrow partner may not be as deep as the allowance is wide: take its nearest point.
  out.location = surface_.chart(src_piece).locator.nearest(out.position_mm);
  return out;
}

std::vector<std::array<Vec2, 2>> AllowanceSource::source_breaks(int piece, double length_mm) const {
  std::vector<std::array<Vec2, 2>> out;
  const PieceChart& c = surface_.chart(piece);
  const auto& m = mitre_[static_cast<size_t>(piece)];
  const size_t n = c.segments.size();
  for (size_t k = 0; k < n; ++k) {
    const BoundarySegment& prev = c.segments[(k + n - 1) % n];
    const BoundarySegment& cur = c.segments[k];
    const bool source_changes = prev.partner_piece != cur.partner_piece ||
                                (cur.partner_piece >= 0 && prev.partner_segment + (prev.partner_reversed ? -1 : 1) != cur.partner_segment &&
                                 prev.partner_segment != cur.partner_segment + (cur.partner_reversed ? 1 : -1));
    const Vec2 v = vertex_position(surface_, piece, c.loop[k]);
    const Vec2 d0 = normalized(v - vertex_position(surface_, piece, prev.a));
    const Vec2 d1 = normalized(vertex_position(surface_, piece, cur.b) - v);
    const bool sharp = dot(d0, d1) < std::cos(kSharpTurn_rad);
    if (!source_changes && !sharp) continue;
    out.push_back({v, v + normalized(m[k]) * length_mm});
  }
  return out;
}

AllowanceSample AllowanceSource::source(int piece, Vec2 p) const {
  return source(piece, seam_coordinates(piece, p));
}

}  // namespace tp::geometry::internal
