// geometry/pattern/orient.cpp: outline reversal with notches, darts and stitches kept consistent.
#include "geometry/pattern/orient.h"

#include <algorithm>

#include "geometry/pattern/curve.h"

namespace tp::geometry {

void reverse_outline(Piece& piece) {
  const int n = static_cast<int>(piece.edges.size());
  std::vector<double> lengths(n);
  for (int i = 0; i < n; ++i) lengths[i] = edge_length_mm(piece.edges[i]);
  std::reverse(piece.edges.begin(), piece.edges.end());
  for (Edge& e : piece.edges) e = reversed_edge(e);
  auto map = [n](int i) { return (i >= 0 && i < n) ? n - 1 - i : i; };
  for (Notch& nt : piece.notches) {
    if (nt.edge >= 0 && nt.edge < n) nt.position_mm = std::max(0.0, lengths[nt.edge] - nt.position_mm);
    nt.edge = map(nt.edge);
  }
  // Legs swap too so leg_a stays the first leg along the outline.
  for (Dart& d : piece.darts) {
    int a = map(d.leg_a), b = map(d.leg_b);
    d.leg_a = b;
    d.leg_b = a;
  }
  if (piece.fold_edge) piece.fold_edge = map(*piece.fold_edge);
}

std::vector<std::string> orient_counter_clockwise(Pattern& pattern) {
  std::vector<std::string> reversed;
  for (int p = 0; p < static_cast<int>(pattern.pieces.size()); ++p) {
    Piece& piece = pattern.pieces[p];
    if (signed_area(outline(piece)) >= 0) continue;
    const int n = static_cast<int>(piece.edges.size());
    // Spans first, while the edge lengths still belong to the old indices.
    for (Stitch& st : pattern.stitches) {
      for (EdgeSpan* sp : {&st.a, &st.b}) {
        if (sp->piece != p || sp->edge < 0 || sp->edge >= n) continue;
        double len = edge_length_mm(piece.edges[sp->edge]);
        double to = sp->to_mm < 0 ? len : sp->to_mm;
        double from = sp->from_mm;
        sp->from_mm = std::max(0.0, len - to);
        sp->to_mm = (from <= 0) ? -1 : len - from;
        sp->edge = n - 1 - sp->edge;
        st.same_direction = !st.same_direction;
      }
    }
    reverse_outline(piece);
    reversed.push_back(piece.name);
  }
  return reversed;
}

}  // namespace tp::geometry
