// geometry/design/internal/depth_map.h: the garment seen from a planar projection's image plane,
// so the image lands only on the surface facing it, never through to the back.
#pragma once

#include <array>
#include <vector>

#include "geometry/common/vec.h"
#include "geometry/design/internal/garment_surface.h"
#include "geometry/design/internal/texture_fields.h"

namespace tp::geometry::internal {

/// Orthographic z-buffer of the garment in the image plane (front-most depth per cell).
class DepthMap {
 public:
  enum class Coverage { kVisible, kHidden, kPartial };

  /// Cells are `min_cell_mm` (0.5 mm for print) or coarser, at most 2048 on a side.
  DepthMap(const PlanarField& field, const GarmentSurface& surface, double tolerance_mm, double min_cell_mm = 0.5);

  /// Visibility 0..1 of a point given in plane coordinates (x, y, depth), filtered over the four
  /// nearest cells (percentage-closer filtering) so shadow edges are smooth.
  double visibility(Vec3 plane_xyz) const;

  /// Whether a triangle (plane coordinates of its corners) is certainly visible, certainly hidden,
  /// or needs the per-pixel test.
  Coverage classify(const std::array<Vec3, 3>& plane_xyz) const;

  double cell_mm() const { return cell_mm_; }

 private:
  double front(int ix, int iy) const;
  Vec2 origin_;
  double cell_mm_ = 1;
  int nx_ = 0, ny_ = 0;
  double tolerance_mm_ = 3;
  std::vector<float> depth_;  // front-most depth per cell, -inf where nothing projects
};

}  // namespace tp::geometry::internal
