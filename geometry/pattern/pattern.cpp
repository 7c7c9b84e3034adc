// geometry/pattern/pattern.cpp: small queries over the pattern model.
#include "geometry/pattern/pattern.h"

#include <algorithm>

namespace tp::geometry {

Polygon outline(const Piece& piece) {
  Polygon poly;
  for (const Edge& e : piece.edges) {
    // Each edge contributes all its points but the last, which is the next edge's start.
    for (size_t i = 0; i + 1 < e.points_mm.size(); ++i) poly.push_back(e.points_mm[i]);
  }
  return poly;
}

double edge_length_mm(const Edge& edge) {
  double len = 0;
  for (size_t i = 1; i < edge.points_mm.size(); ++i) len += norm(edge.points_mm[i] - edge.points_mm[i - 1]);
  return len;
}

int find_piece(const Pattern& pattern, const std::string& name) {
  for (size_t i = 0; i < pattern.pieces.size(); ++i)
    if (pattern.pieces[i].name == name) return static_cast<int>(i);
  return -1;
}

int find_edge(const Piece& piece, const std::string& name) {
  for (size_t i = 0; i < piece.edges.size(); ++i)
    if (piece.edges[i].name == name) return static_cast<int>(i);
  return -1;
}

Vec2 point_along_edge(const Edge& edge, double s_mm) {
  const auto& pts = edge.points_mm;
  if (pts.empty()) return {};
  if (s_mm <= 0) return pts.front();
  // Walk the polyline until the segment holding arc length s_mm.
  double acc = 0;
  for (size_t i = 1; i < pts.size(); ++i) {
    double seg = norm(pts[i] - pts[i - 1]);
    if (acc + seg >= s_mm && seg > 0) return pts[i - 1] + (pts[i] - pts[i - 1]) * ((s_mm - acc) / seg);
    acc += seg;
  }
  return pts.back();
}

Vec2 tangent_along_edge(const Edge& edge, double s_mm) {
  const auto& pts = edge.points_mm;
  // The segment holding s_mm; zero-length segments are skipped so a tangent always has a direction.
  double acc = 0;
  Vec2 last{};
  for (size_t i = 1; i < pts.size(); ++i) {
    Vec2 d = pts[i] - pts[i - 1];
    double seg = norm(d);
    if (seg <= 0) continue;
    last = d / seg;
    if (acc + seg >= s_mm) return last;
    acc += seg;
  }
  return last;
}

std::array<double, 2> span_range_mm(const Pattern& pattern, const EdgeSpan& span) {
  if (span.piece < 0 || span.piece >= static_cast<int>(pattern.pieces.size())) return {0, 0};
  const Piece& piece = pattern.pieces[span.piece];
  if (span.edge < 0 || span.edge >= static_cast<int>(piece.edges.size())) return {0, 0};
  double len = edge_length_mm(piece.edges[span.edge]);
  double to = span.to_mm < 0 ? len : span.to_mm;
  return {span.from_mm, to};
}

double span_length_mm(const Pattern& pattern, const EdgeSpan& span) {
  auto r = span_range_mm(pattern, span);
  return std::max(0.0, r[1] - r[0]);
}

std::string describe_edge(const Pattern& pattern, int piece, int edge) {
  if (piece < 0 || piece >= static_cast<int>(pattern.pieces.size()))
    return "piece #" + std::to_string(piece);
  const Piece& p = pattern.pieces[piece];
  std::string s = "piece '" + p.name + "'";
  if (edge < 0 || edge >= static_cast<int>(p.edges.size())) return s + " edge #" + std::to_string(edge);
  return s + " edge '" + p.edges[edge].name + "' (" + std::to_string(edge) + ")";
}

}  // namespace tp::geometry
