// geometry/pattern/import/internal/outline_projection.cpp: nearest outline point (see the header).
#include "geometry/pattern/import/internal/outline_projection.h"

#include <algorithm>
#include <cmath>

namespace tp::geometry::internal {

Projection project(const Piece& piece, Vec2 at) {
  Projection best;
  for (int e = 0; e < static_cast<int>(piece.edges.size()); ++e) {
    const auto& pts = piece.edges[e].points_mm;
    double acc = 0;
    for (size_t i = 1; i < pts.size(); ++i) {
      Vec2 ab = pts[i] - pts[i - 1];
      double len = norm(ab);
      double t = len > 0 ? std::clamp(dot(at - pts[i - 1], ab) / (len * len), 0.0, 1.0) : 0;
      double d = norm(at - (pts[i - 1] + ab * t));
      if (d < best.distance_mm) best = Projection{e, acc + t * len, d};
      acc += len;
    }
  }
  return best;
}

double distance_to_line(Vec2 x, Vec2 p, Vec2 q) { return std::abs(cross(normalized(q - p), x - p)); }

}  // namespace tp::geometry::internal
