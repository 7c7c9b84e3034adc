// geometry/design/internal/texture_fields.h: image layers as exact functions of the surface point:
// texture coordinates (level-0 texels) and a weight, evaluated at construction time only; the
// renderer interpolates them linearly inside small triangles.
#pragma once

#include <memory>
#include <vector>

#include "geometry/design/design.h"
#include "geometry/design/fit_cylinder.h"
#include "geometry/design/internal/closest_point.h"
#include "geometry/design/internal/garment_surface.h"
#include "geometry/design/raster/mip_cache.h"
#include "geometry/design/raster/mip_image.h"

namespace tp::geometry::internal {

/// Texture coordinates in level-0 texels (texel centres at half-integers) and a weight 0..1.
struct FieldSample {
  double u = 0, v = 0, w = 0;
};

/// One image layer's mapping from the garment surface to its image.
class TextureField {
 public:
  virtual ~TextureField() = default;
  /// Exact texture coordinates at a surface point.
  virtual FieldSample eval(const SurfacePoint& p) const = 0;
  /// Texels per full period of u (a cylinder's circumference) or 0 when u does not wrap.
  virtual double period_u() const { return 0; }

  std::shared_ptr<const MipImage> image;
  /// Largest acceptable error of linear interpolation inside a render triangle, in texels.
  double tolerance_texels = 0.01;
};

// Each field's image pyramid comes from `mips` when given (kept between designs), else is built.

/// Cylindrical projection around a cylinder (fitted to the garment unless given).
std::unique_ptr<TextureField> make_cylindrical_field(const CylindricalProjection& layer, const GarmentSurface& surface,
                                                     double tolerance_mm, MipCache* mips = nullptr);

/// Planar projection: plane coordinates, facing weight; occlusion is the DepthMap's job.
class PlanarField : public TextureField {
 public:
  PlanarField(const PlanarProjection& layer, double tolerance_mm, MipCache* mips = nullptr);
  FieldSample eval(const SurfacePoint& p) const override;
  /// Plane coordinates (mm along right, up) and depth (mm towards the image) of a point.
  Vec3 plane_coordinates(Vec3 p) const;
  /// The image's rectangle in plane coordinates (mm), or an empty box when it repeats.
  Box2 image_box_mm() const;

 private:
  Vec3 centre_, normal_, right_, up_;
  double width_mm_, height_mm_;
  double cos_full_, cos_zero_;
};

/// Texture transfer from a textured model of the same garment by closest point.
std::unique_ptr<TextureField> make_transfer_field(const TextureTransfer& layer, double tolerance_mm,
                                                  MipCache* mips = nullptr);

}  // namespace tp::geometry::internal
