// tests/geometry/sewing/sheet_fixture.h: flat sheets as one-piece garments for the cloth tests.
#pragma once

#include <functional>

#include "geometry/garment/garment.h"

namespace tp::geometry::test_fixture {

/// A grid piece of `cols` x `rows` cells of `step_mm` (two triangles each), its 2D corner (i, j)
/// at (i, j) x step and in 3D at place(i, j), appended to `g` as a new piece.
inline void add_grid_piece(Garment& g, int cols, int rows, double step_mm,
                           const std::function<Vec3(int i, int j)>& place) {
  GarmentPiece gp;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) {
      gp.mesh.vertices_mm.push_back({i * step_mm, j * step_mm});
      gp.vertex_3d.push_back(static_cast<int>(g.vertices_mm.size()));
      g.vertices_mm.push_back(place(i, j));
    }
  const auto id = [&](int i, int j) { return j * (cols + 1) + i; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      gp.mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      gp.mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  g.pieces.push_back(std::move(gp));
}

/// A square sheet of side `side_mm` as one piece (a regular grid, `cells` per side), lying flat
/// at height y_mm centred over the origin, its 2D y running along -z.
inline Garment flat_sheet(double side_mm, int cells, double y_mm) {
  Garment g;
  const double step = side_mm / cells;
  add_grid_piece(g, cells, cells, step, [&](int i, int j) {
    return Vec3{i * step - side_mm / 2, y_mm, side_mm / 2 - j * step};
  });
  return g;
}

}  // namespace tp::geometry::test_fixture
