// geometry/samples/internal/draft.cpp: drafting helpers: Bezier edges, darts, mirrored pieces, stitches.
#include "geometry/samples/internal/draft.h"

#include <algorithm>
#include <cmath>

#include "geometry/common/tolerances.h"

namespace tp::geometry::samples::internal {
namespace {

// Curves are flattened to about one point per this many mm (at least 16 segments).
constexpr double kFlattenStepMm = 4;

int segments_for(double approx_len_mm) { return std::max(16, static_cast<int>(std::ceil(approx_len_mm / kFlattenStepMm))); }

double polyline_length(const std::vector<Vec2>& pts) {
  double l = 0;
  for (size_t i = 1; i < pts.size(); ++i) l += norm(pts[i] - pts[i - 1]);
  return l;
}

// Splits a polyline at arc length s: points up to s (inclusive) and from s on.
std::pair<std::vector<Vec2>, std::vector<Vec2>> split_at(const std::vector<Vec2>& pts, double s) {
  std::vector<Vec2> a{pts.front()}, b;
  double acc = 0;
  size_t i = 1;
  for (; i < pts.size(); ++i) {
    double seg = norm(pts[i] - pts[i - 1]);
    if (acc + seg >= s) break;
    acc += seg;
    a.push_back(pts[i]);
  }
  if (i >= pts.size()) return {pts, {pts.back(), pts.back()}};
  double seg = norm(pts[i] - pts[i - 1]);
  Vec2 cut = seg > 0 ? pts[i - 1] + (pts[i] - pts[i - 1]) * ((s - acc) / seg) : pts[i - 1];
  if (norm(cut - a.back()) > kSamePoint_mm) a.push_back(cut);
  b.push_back(cut);
  for (; i < pts.size(); ++i)
    if (norm(pts[i] - b.back()) > kSamePoint_mm) b.push_back(pts[i]);
  if (b.size() < 2) b.push_back(pts.back());
  return {a, b};
}

}  // namespace

std::vector<Vec2> cubic_points(Vec2 p0, Vec2 c1, Vec2 c2, Vec2 p1, int segments) {
  std::vector<Vec2> out;
  for (int i = 0; i <= segments; ++i) {
    double t = static_cast<double>(i) / segments, u = 1 - t;
    out.push_back(p0 * (u * u * u) + c1 * (3 * u * u * t) + c2 * (3 * u * t * t) + p1 * (t * t * t));
  }
  return out;
}

OutlineBuilder& OutlineBuilder::line(const std::string& name, Vec2 to) {
  edges_.push_back(Edge{name, EdgeCurve::kLine, {}, {cursor_, to}});
  cursor_ = to;
  return *this;
}

OutlineBuilder& OutlineBuilder::quad(const std::string& name, Vec2 c, Vec2 to) {
  Edge e{name, EdgeCurve::kQuadratic, {c}, {}};
  int n = segments_for(norm(c - cursor_) + norm(to - c));
  for (int i = 0; i <= n; ++i) {
    double t = static_cast<double>(i) / n, u = 1 - t;
    e.points_mm.push_back(cursor_ * (u * u) + c * (2 * u * t) + to * (t * t));
  }
  edges_.push_back(std::move(e));
  cursor_ = to;
  return *this;
}

OutlineBuilder& OutlineBuilder::cubic(const std::string& name, Vec2 c1, Vec2 c2, Vec2 to) {
  Edge e{name, EdgeCurve::kCubic, {c1, c2}, {}};
  e.points_mm = cubic_points(cursor_, c1, c2, to, segments_for(norm(c1 - cursor_) + norm(c2 - c1) + norm(to - c2)));
  edges_.push_back(std::move(e));
  cursor_ = to;
  return *this;
}

OutlineBuilder& OutlineBuilder::polyline(const std::string& name, const std::vector<Vec2>& pts) {
  Edge e{name, EdgeCurve::kPolyline, {}, {cursor_}};
  for (Vec2 p : pts)
    if (norm(p - e.points_mm.back()) > kSamePoint_mm) e.points_mm.push_back(p);
  edges_.push_back(std::move(e));
  cursor_ = pts.back();
  return *this;
}

std::pair<int, int> cut_dart(Piece& piece, int edge, double centre_mm, double width_mm, Vec2 apex, const std::string& dart) {
  Edge old = piece.edges[edge];
  double len = polyline_length(old.points_mm);
  double s0 = std::clamp(centre_mm - width_mm / 2, 0.0, len), s1 = std::clamp(centre_mm + width_mm / 2, 0.0, len);
  auto [before, rest] = split_at(old.points_mm, s0);
  auto [mouth, after] = split_at(rest, s1 - s0);
  Vec2 m0 = before.back(), m1 = after.front();
  // Equal legs: the point goes onto the mouth's perpendicular bisector.
  Vec2 mid = (m0 + m1) * 0.5, dir = normalized(perp(m1 - m0));
  Vec2 tip = mid + dir * dot(apex - mid, dir);
  Edge e0{old.name, EdgeCurve::kPolyline, {}, before};
  Edge la{dart + "_a", EdgeCurve::kLine, {}, {m0, tip}};
  Edge lb{dart + "_b", EdgeCurve::kLine, {}, {tip, m1}};
  Edge e1{old.name + "_2", EdgeCurve::kPolyline, {}, after};
  if (old.curve == EdgeCurve::kLine) e0.curve = e1.curve = EdgeCurve::kLine;
  piece.edges.erase(piece.edges.begin() + edge);
  piece.edges.insert(piece.edges.begin() + edge, {e0, la, lb, e1});
  // Later notches and darts move down by three edges.
  for (Notch& n : piece.notches) {
    if (n.edge > edge) n.edge += 3;
    else if (n.edge == edge && n.position_mm > s1) n.edge += 3, n.position_mm -= s1;
  }
  for (Dart& d : piece.darts) {
    if (d.leg_a > edge) d.leg_a += 3;
    if (d.leg_b > edge) d.leg_b += 3;
  }
  piece.darts.push_back(Dart{dart, edge + 1, edge + 2});
  piece.drill_holes.push_back(DrillHole{tip + (mid - tip) * (10.0 / std::max(norm(mid - tip), 10.0)), 3});
  return {edge + 1, edge + 2};
}

Piece mirror_piece(const Piece& src, const std::string& name) {
  Piece p = src;
  p.name = name;
  p.mirrored = !src.mirrored;
  const int n = static_cast<int>(src.edges.size());
  const auto map_edge = [n](int e) { return n - 1 - e; };
  p.edges.clear();
  for (int e = n - 1; e >= 0; --e) {
    Edge m = src.edges[e];
    std::reverse(m.points_mm.begin(), m.points_mm.end());
    for (Vec2& q : m.points_mm) q.x = -q.x;
    std::reverse(m.control_mm.begin(), m.control_mm.end());
    for (Vec2& q : m.control_mm) q.x = -q.x;
    p.edges.push_back(std::move(m));
  }
  for (Notch& nt : p.notches) {
    double l = polyline_length(src.edges[nt.edge].points_mm);
    nt.edge = map_edge(nt.edge);
    nt.position_mm = l - nt.position_mm;
  }
  for (Dart& d : p.darts) {
    int a = map_edge(d.leg_b), b = map_edge(d.leg_a);
    d.leg_a = a, d.leg_b = b;
  }
  if (p.grain) p.grain = GrainLine{{-src.grain->from_mm.x, src.grain->from_mm.y}, {-src.grain->to_mm.x, src.grain->to_mm.y}};
  if (p.fold_edge) p.fold_edge = map_edge(*p.fold_edge);
  for (InternalLine& l : p.internal_lines)
    for (Vec2& q : l.points_mm) q.x = -q.x;
  for (DrillHole& h : p.drill_holes) h.position_mm.x = -h.position_mm.x;
  // The mirror image sits mirrored across the body's x = 0 plane: R' = M R M, t' = M t.
  if (p.placement) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if ((i == 0) != (j == 0)) p.placement->rotation[i * 3 + j] = -p.placement->rotation[i * 3 + j];
    p.placement->translation_mm.x = -p.placement->translation_mm.x;
  }
  return p;
}

Placement3d placement_about_y(double theta, Vec3 t) {
  double c = std::cos(theta), s = std::sin(theta);
  return Placement3d{{c, 0, s, 0, 1, 0, -s, 0, c}, t};
}

Status add_stitch(Pattern& p, const std::string& pa, const std::string& ea, const std::string& pb, const std::string& eb,
                  double a_from, double a_to, double b_from, double b_to) {
  int ia = find_piece(p, pa), ib = find_piece(p, pb);
  if (ia < 0) return fail(ErrorCode::kUnknownReference, "no piece '" + pa + "'");
  if (ib < 0) return fail(ErrorCode::kUnknownReference, "no piece '" + pb + "'");
  int ja = find_edge(p.pieces[ia], ea), jb = find_edge(p.pieces[ib], eb);
  if (ja < 0) return fail(ErrorCode::kUnknownReference, "piece '" + pa + "' has no edge '" + ea + "'");
  if (jb < 0) return fail(ErrorCode::kUnknownReference, "piece '" + pb + "' has no edge '" + eb + "'");
  p.stitches.push_back(Stitch{EdgeSpan{ia, ja, a_from, a_to}, EdgeSpan{ib, jb, b_from, b_to}, false});
  return {};
}

Status stitch_darts(Pattern& p) {
  for (size_t i = 0; i < p.pieces.size(); ++i)
    for (const Dart& d : p.pieces[i].darts)
      p.stitches.push_back(Stitch{EdgeSpan{static_cast<int>(i), d.leg_a, 0, -1}, EdgeSpan{static_cast<int>(i), d.leg_b, 0, -1}, false});
  return {};
}

double edge_length(const Pattern& p, const std::string& piece, const std::string& edge) {
  int i = find_piece(p, piece);
  if (i < 0) return 0;
  int e = find_edge(p.pieces[i], edge);
  return e < 0 ? 0 : edge_length_mm(p.pieces[i].edges[e]);
}

void add_notch(Piece& piece, const std::string& edge, double position_mm, const std::string& name) {
  int e = find_edge(piece, edge);
  if (e >= 0) piece.notches.push_back(Notch{name, e, position_mm, NotchType::kSlit});
}

}  // namespace tp::geometry::samples::internal
