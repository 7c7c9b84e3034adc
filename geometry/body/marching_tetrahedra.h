// geometry/body/marching_tetrahedra.h: closed triangle mesh of the zero set of a sampled scalar field.
#pragma once

#include <functional>

#include "geometry/body/body_mesh.h"
#include "geometry/common/vec.h"

namespace tp::geometry {

/// A scalar field sampled on a regular grid: value(i, j, k) at origin + (i, j, k) * spacing.
struct ScalarGrid {
  Vec3 origin_mm;
  double spacing_mm = 1;
  int nx = 0, ny = 0, nz = 0;
  std::vector<float> values;  ///< nx * ny * nz, x fastest; negative inside

  float at(int i, int j, int k) const { return values[(static_cast<size_t>(k) * ny + j) * nx + i]; }
};

/// Extracts the surface value = 0 of `grid` with marching tetrahedra (six tetrahedra per cell,
/// Kuhn split, so neighbouring cells agree). Vertices on shared grid edges are shared, so the
/// mesh is closed when the field is positive on the grid's border; triangles face the positive
/// side. Returns an empty mesh for an empty grid.
BodyMesh marching_tetrahedra(const ScalarGrid& grid);

}  // namespace tp::geometry
