// geometry/design/internal/texture_fields.cpp: cylindrical, planar and transfer texture fields.
#include "geometry/design/internal/texture_fields.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tp::geometry::internal {
namespace {

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

class CylindricalField : public TextureField {
 public:
  CylindricalField(const CylindricalProjection& layer, const GarmentSurface& surface, double tolerance_mm,
                   MipCache* mips) {
    const Vec3 dir = layer.axis_direction.value_or(Vec3{0, 1, 0});
    cyl_ = fit_cylinder(surface.garment().vertices_mm, dir, layer.axis_origin_mm);
    if (layer.radius_mm > 0) cyl_.radius_mm = layer.radius_mm;
    axis_ = cyl_.direction;
    // θ = 0 faces the front (+z, or +x when the axis is along z); θ grows towards +x.
    Vec3 front = Vec3{0, 0, 1} - axis_ * dot(Vec3{0, 0, 1}, axis_);
    if (norm(front) < 1e-6) front = Vec3{1, 0, 0} - axis_ * dot(Vec3{1, 0, 0}, axis_);
    e0_ = normalized(front);
    e1_ = cross(axis_, e0_);
    const double circumference = 2 * std::numbers::pi * std::max(cyl_.radius_mm, 1e-6);
    const int tiles =
        layer.tile_width_mm > 0 ? std::max(1, static_cast<int>(std::lround(circumference / layer.tile_width_mm))) : 1;
    tile_w_mm_ = circumference / tiles;
    W_ = layer.image->width_px;
    H_ = layer.image->height_px;
    tile_h_mm_ = layer.tile_height_mm > 0 ? layer.tile_height_mm : tile_w_mm_ * H_ / W_;
    period_ = static_cast<double>(tiles) * W_;
    rotation_rad_ = layer.rotation_deg * std::numbers::pi / 180.0;
    offset_ = layer.offset_mm;
    top_ = cyl_.max_height_mm;
    image = mip_of(layer.image, Wrap::kRepeat, layer.repeat ? Wrap::kRepeat : Wrap::kTransparent, mips);
    tolerance_texels = tolerance_mm / (tile_w_mm_ / W_);
  }

  FieldSample eval(const SurfacePoint& p) const override {
    const Vec3 q = p.position_mm - cyl_.origin_mm;
    const double theta = std::atan2(dot(q, e1_), dot(q, e0_)) + rotation_rad_;
    // The tile's horizontal centre faces the front; arc length is measured on the cylinder.
    const double around_mm = theta * cyl_.radius_mm + 0.5 * tile_w_mm_ - offset_.x;
    const double along_mm = (top_ - dot(q, axis_)) - offset_.y;
    return {around_mm / tile_w_mm_ * W_, along_mm / tile_h_mm_ * H_, 1.0};
  }
  double period_u() const override { return period_; }

 private:
  Cylinder cyl_;
  Vec3 axis_, e0_, e1_;
  double tile_w_mm_ = 1, tile_h_mm_ = 1, period_ = 0, rotation_rad_ = 0, top_ = 0;
  Vec2 offset_;
  int W_ = 1, H_ = 1;
};

class TransferField : public TextureField {
 public:
  TransferField(const TextureTransfer& layer, double tolerance_mm, MipCache* mips)
      : index_(layer.vertices_mm, layer.triangles), layer_(layer) {
    W_ = layer.image->width_px;
    H_ = layer.image->height_px;
    image = mip_of(layer.image, Wrap::kRepeat, Wrap::kRepeat, mips);
    // Surface mm per texel from the model's total 3D area over its total texel area.
    double area3 = 0, area_tex = 0;
    for (size_t t = 0; t < layer.triangles.size(); ++t) {
      const auto& f = layer.triangles[t];
      const auto& g = layer.uv_triangles[t];
      const Vec3 a = layer.vertices_mm[static_cast<size_t>(f[0])], b = layer.vertices_mm[static_cast<size_t>(f[1])],
                 c = layer.vertices_mm[static_cast<size_t>(f[2])];
      area3 += 0.5 * norm(cross(b - a, c - a));
      const Vec2 ua = uv_texels(g[0]), ub = uv_texels(g[1]), uc = uv_texels(g[2]);
      area_tex += 0.5 * std::abs(geometry::cross(ub - ua, uc - ua));
    }
    const double texel_mm = area_tex > 0 ? std::sqrt(area3 / area_tex) : 1.0;
    tolerance_texels = tolerance_mm / texel_mm;
  }

  FieldSample eval(const SurfacePoint& p) const override {
    const MeshHit hit = index_.nearest(p.position_mm);
    if (hit.triangle < 0) return {};
    const auto& g = layer_.uv_triangles[static_cast<size_t>(hit.triangle)];
    Vec2 uv;
    for (int k = 0; k < 3; ++k) uv += uv_texels(g[static_cast<size_t>(k)]) * hit.bary[static_cast<size_t>(k)];
    return {uv.x, uv.y, hit.distance_mm <= layer_.max_distance_mm ? 1.0 : 0.0};
  }

 private:
  Vec2 uv_texels(int i) const {
    const Vec2 uv = layer_.uvs[static_cast<size_t>(i)];
    return {uv.x * W_, (1.0 - uv.y) * H_};  // v points up in UV space, rows go down
  }
  ClosestPointIndex index_;
  TextureTransfer layer_;  // a copy: the renderer outlives the caller's design
  int W_ = 1, H_ = 1;
};

}  // namespace

std::unique_ptr<TextureField> make_cylindrical_field(const CylindricalProjection& layer, const GarmentSurface& surface,
                                                     double tolerance_mm, MipCache* mips) {
  return std::make_unique<CylindricalField>(layer, surface, tolerance_mm, mips);
}

std::unique_ptr<TextureField> make_transfer_field(const TextureTransfer& layer, double tolerance_mm, MipCache* mips) {
  return std::make_unique<TransferField>(layer, tolerance_mm, mips);
}

PlanarField::PlanarField(const PlanarProjection& layer, double tolerance_mm, MipCache* mips) {
  centre_ = layer.centre_mm;
  normal_ = normalized(layer.normal);
  up_ = normalized(layer.up - normal_ * dot(layer.up, normal_));
  // A viewer looking along -normal with `up` up sees `right` to the right.
  right_ = cross(-normal_, up_);
  const int W = layer.image->width_px, H = layer.image->height_px;
  width_mm_ = layer.width_mm;
  height_mm_ = layer.height_mm > 0 ? layer.height_mm : layer.width_mm * H / W;
  cos_full_ = std::cos(layer.fade_start_deg * std::numbers::pi / 180.0);
  cos_zero_ = std::cos(layer.fade_end_deg * std::numbers::pi / 180.0);
  const Wrap wrap = layer.repeat ? Wrap::kRepeat : Wrap::kTransparent;
  image = mip_of(layer.image, wrap, wrap, mips);
  tolerance_texels = tolerance_mm / (width_mm_ / W);
}

Vec3 PlanarField::plane_coordinates(Vec3 p) const {
  const Vec3 q = p - centre_;
  return {dot(q, right_), dot(q, up_), dot(q, normal_)};
}

Box2 PlanarField::image_box_mm() const {
  Box2 b;
  if (image->wrap_u() == Wrap::kRepeat || image->wrap_v() == Wrap::kRepeat) return b;
  b.add({-width_mm_ / 2, -height_mm_ / 2});
  b.add({width_mm_ / 2, height_mm_ / 2});
  return b;
}

FieldSample PlanarField::eval(const SurfacePoint& p) const {
  const Vec3 c = plane_coordinates(p.position_mm);
  const double facing = dot(p.normal, normal_);
  const double w =
      cos_full_ > cos_zero_ ? smoothstep((facing - cos_zero_) / (cos_full_ - cos_zero_)) : (facing > 0 ? 1.0 : 0.0);
  return {(c.x / width_mm_ + 0.5) * image->width(), (0.5 - c.y / height_mm_) * image->height(), w};
}

}  // namespace tp::geometry::internal
