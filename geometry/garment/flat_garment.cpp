// geometry/garment/flat_garment.cpp: pieces laid side by side in the plane as their own 3D garment.
#include "geometry/garment/flat_garment.h"

#include <string>

namespace tp::geometry {

Result<Garment> flat_garment(const Pattern& pattern, const PatternMesh& meshes) {
  if (meshes.pieces.size() != pattern.pieces.size())
    return fail(ErrorCode::kInvalidArgument, "flat garment: " + std::to_string(meshes.pieces.size()) +
                                                 " meshes for " + std::to_string(pattern.pieces.size()) + " pieces");
  Garment g;
  double next_x_mm = 0;
  for (size_t i = 0; i < pattern.pieces.size(); ++i) {
    const PieceMesh& m = meshes.pieces[i];
    if (m.vertices_mm.empty())
      return fail(ErrorCode::kInvalidArgument, "flat garment: piece '" + pattern.pieces[i].name + "' has no mesh");
    Box2 box;
    for (Vec2 p : m.vertices_mm) box.add(p);
    // Shift so this piece starts at next_x_mm and rests on y = 0.
    const Vec2 shift{next_x_mm - box.min.x, -box.min.y};
    GarmentPiece gp;
    gp.piece = static_cast<int>(i);
    gp.mesh = m;
    gp.vertex_3d.reserve(m.vertices_mm.size());
    for (Vec2 p : m.vertices_mm) {
      gp.vertex_3d.push_back(static_cast<int>(g.vertices_mm.size()));
      g.vertices_mm.push_back({p.x + shift.x, p.y + shift.y, 0});
    }
    g.pieces.push_back(std::move(gp));
    next_x_mm += box.width() + kFlatLayoutGap_mm;
  }
  return g;
}

}  // namespace tp::geometry
