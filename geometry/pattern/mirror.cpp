// geometry/pattern/mirror.cpp: mirror-image copies of pieces and their 3D placement.
#include "geometry/pattern/mirror.h"

#include "geometry/pattern/curve.h"
#include "geometry/pattern/orient.h"

namespace tp::geometry {

Piece mirrored_piece(const Piece& piece) {
  const Affine2 flip = Affine2::scale(-1, 1);
  Piece m = piece;
  for (Edge& e : m.edges) e = transformed_edge(e, flip);
  // A reflection turns the outline clockwise; reversing it restores the orientation.
  reverse_outline(m);
  if (m.grain) m.grain = GrainLine{flip.apply(m.grain->from_mm), flip.apply(m.grain->to_mm)};
  if (m.fold_line_mm) m.fold_line_mm = std::array<Vec2, 2>{flip.apply((*m.fold_line_mm)[0]), flip.apply((*m.fold_line_mm)[1])};
  for (InternalLine& l : m.internal_lines)
    for (Vec2& p : l.points_mm) p = flip.apply(p);
  for (DrillHole& h : m.drill_holes) h.position_mm = flip.apply(h.position_mm);
  if (m.placement) {
    // p3d' = S3 (R p + t) with p = S2 p': R' = S3 R S2 (negate row 0 and column 0), t' = S3 t.
    auto& r = m.placement->rotation;
    r[1] = -r[1];
    r[2] = -r[2];
    r[3] = -r[3];
    r[6] = -r[6];
    m.placement->translation_mm.x = -m.placement->translation_mm.x;
  }
  m.mirrored = !piece.mirrored;
  return m;
}

}  // namespace tp::geometry
