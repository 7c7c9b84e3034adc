// geometry/garment/garment.h: the piece/garment correspondence (DESIGN.md decision 2).
//
// Each piece is triangulated once and the 3D garment has the same triangles. A 3D vertex on a
// seam is shared by the joining pieces; each piece keeps its own 2D coordinate for it (one
// texture coordinate per joining piece, the paper's section 3.4).
#pragma once

#include <vector>

#include "geometry/common/vec.h"
#include "geometry/mesh/piece_mesh.h"

namespace tp::geometry {

/// One piece's chart: its 2D mesh and where each of its vertices lives in 3D.
struct GarmentPiece {
  int piece = 0;                 ///< index into Pattern::pieces
  PieceMesh mesh;                ///< 2D, piece-local mm (the texture coordinates)
  std::vector<int> vertex_3d;    ///< #mesh.V: index into Garment::vertices_mm
};

/// The 3D garment: shared 3D vertices and one chart per piece.
struct Garment {
  std::vector<Vec3> vertices_mm;     ///< 3D positions in mm (body frame: y up, z forward)
  std::vector<GarmentPiece> pieces;  ///< same order as Pattern::pieces
};

}  // namespace tp::geometry
