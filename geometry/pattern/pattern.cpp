// geometry/pattern/pattern.cpp: small queries over the pattern model.
#include "geometry/pattern/pattern.h"

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

}  // namespace tp::geometry
