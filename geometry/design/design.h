// geometry/design/design.h: print design layers made on the 3D garment (paper section 3.5).
//
// Every layer is a function of the 3D surface point (DESIGN.md decision 2); layers are
// composited in order, each with its own opacity, over an unprinted (transparent) fabric.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geometry/common/image.h"
#include "geometry/common/vec.h"

namespace tp::geometry {

/// A tileable image rolled onto a cylinder fitted around the garment and projected inwards.
struct CylindricalProjection {
  ImageHandle image;
  std::optional<Vec3> axis_origin_mm;   ///< a point on the axis; fitted to the garment if absent
  std::optional<Vec3> axis_direction;   ///< unit axis (default: body up, +y)
  double radius_mm = 0;                 ///< cylinder radius; 0 = fitted closely around the garment
  /// Arc length one image width covers; 0 = once around. Rounded so that a whole number of tiles
  /// goes around the cylinder (the wrap is seamless, as the paper's rolled rectangle is).
  double tile_width_mm = 0;
  double tile_height_mm = 0;            ///< height one image covers; 0 = keep the image aspect
  double rotation_deg = 0;              ///< rotation of the image about the axis
  Vec2 offset_mm;                       ///< (around, along) shift of the image
  bool repeat = true;                   ///< tile along the axis (around always wraps)
};
// The image's horizontal centre faces the front (+z) and its top edge is at the garment's top;
// u grows towards the wearer's left (+x), as a viewer in front sees it.

/// An image placed in 3D and projected along its normal onto the surface facing it.
struct PlanarProjection {
  ImageHandle image;
  Vec3 centre_mm;
  Vec3 normal{0, 0, 1};                 ///< points from the image towards the garment's outside
  Vec3 up{0, 1, 0};
  double width_mm = 100;
  double height_mm = 0;                 ///< 0 = keep the image aspect
  bool repeat = false;
  /// Surfaces turned away from the image fade out between these angles (normal vs `normal`).
  double fade_start_deg = 70;
  double fade_end_deg = 88;
  /// Surface farther than this behind the front-most surface (along the projection) is occluded.
  double occlusion_tolerance_mm = 3;
};

/// A brush stroke painted on the 3D surface; distances are measured on the garment.
struct BrushStroke {
  std::vector<Vec3> points_mm;          ///< polyline of surface points (snapped to the surface)
  double radius_mm = 5;
  Rgba8 colour{0, 0, 0, 255};
  double hardness = 0.8;                ///< 1 = hard edge, 0 = soft falloff over the radius
};

/// A textured 3D model of the same garment painted in another tool, re-sampled onto the pieces.
struct TextureTransfer {
  ImageHandle image;
  std::vector<Vec3> vertices_mm;
  std::vector<Vec2> uvs;                ///< texture coordinates, 0..1, v up
  std::vector<std::array<int, 3>> triangles;       ///< into vertices_mm
  std::vector<std::array<int, 3>> uv_triangles;    ///< into uvs
  double max_distance_mm = 30;          ///< garment points farther from the model stay unprinted
};

/// One design layer.
struct DesignLayer {
  std::string name;
  double opacity = 1.0;
  std::variant<CylindricalProjection, PlanarProjection, BrushStroke, TextureTransfer> content;
};

/// The whole print design of a garment, bottom layer first.
struct Design {
  std::vector<DesignLayer> layers;
};

}  // namespace tp::geometry
