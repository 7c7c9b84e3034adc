// geometry/design/sample_designs.cpp: marbling, motif and stroke designs for the sample garments.
#include "geometry/design/sample_designs.h"

#include <cmath>
#include <memory>
#include <numbers>

#include "geometry/design/fit_cylinder.h"
#include "geometry/design/textures.h"

namespace tp::geometry {
namespace {

DesignLayer marbling_layer(const Cylinder& cyl) {
  CylindricalProjection c;
  c.image = std::make_shared<const ImageRgba8>(marbling());
  // About four tiles around: the pattern reads at garment scale.
  c.tile_width_mm = 2 * std::numbers::pi * cyl.radius_mm / 4;
  return {"marbling", 1.0, c};
}

DesignLayer motif_layer(const Cylinder& cyl) {
  PlanarProjection p;
  p.image = std::make_shared<const ImageRgba8>(placement_motif(512));
  const double height = cyl.max_height_mm - cyl.min_height_mm;
  // On the front, a third of the way down from the top, facing the viewer.
  p.centre_mm = cyl.origin_mm + cyl.direction * (cyl.max_height_mm - 0.3 * height) + Vec3{0, 0, cyl.radius_mm};
  p.normal = {0, 0, 1};
  p.up = cyl.direction;
  p.width_mm = 0.9 * cyl.radius_mm;
  return {"motif", 1.0, p};
}

std::vector<DesignLayer> stroke_layers(const Cylinder& cyl) {
  std::vector<DesignLayer> out;
  const double pi = std::numbers::pi;
  const Vec3 a = cyl.direction;
  const Vec3 front{0, 0, 1}, side = normalized(cross(a, front));
  const double h0 = cyl.min_height_mm, h1 = cyl.max_height_mm;
  const Rgba8 colours[] = {{30, 60, 150, 255}, {200, 60, 40, 255}, {40, 140, 90, 255}, {230, 170, 30, 255}};
  // Rings around the body: points outside the garment, snapped onto it by the stroke.
  for (int i = 0; i < 4; ++i) {
    BrushStroke b;
    const double h = h0 + (h1 - h0) * (0.2 + 0.18 * i);
    for (int k = 0; k <= 96; ++k) {
      const double th = 2 * pi * k / 96;
      b.points_mm.push_back(cyl.origin_mm + a * h + (front * std::cos(th) + side * std::sin(th)) * (cyl.radius_mm + 30));
    }
    b.radius_mm = 6 + 2 * i;
    b.hardness = 0.6;
    b.colour = colours[i];
    out.push_back({"ring " + std::to_string(i + 1), 0.9, b});
  }
  // A diagonal sweep across the front and round both sides.
  BrushStroke sweep;
  for (int k = 0; k <= 64; ++k) {
    const double t = static_cast<double>(k) / 64;
    const double th = -0.6 * pi + 1.2 * pi * t;
    const double h = h0 + (h1 - h0) * (0.85 - 0.6 * t);
    sweep.points_mm.push_back(cyl.origin_mm + a * h + (front * std::cos(th) + side * std::sin(th)) * (cyl.radius_mm + 30));
  }
  sweep.radius_mm = 12;
  sweep.hardness = 0.3;
  sweep.colour = {120, 40, 140, 255};
  out.push_back({"sweep", 0.8, sweep});
  return out;
}

}  // namespace

Design sample_design(std::string_view name, const Garment& garment) {
  const Cylinder cyl = fit_cylinder(garment.vertices_mm, {0, 1, 0});
  Design d;
  if (name == "simple_top") {
    d.layers = stroke_layers(cyl);
    return d;
  }
  d.layers.push_back(marbling_layer(cyl));
  if (name == "dress" || name == "blouse") d.layers.push_back(motif_layer(cyl));
  return d;
}

}  // namespace tp::geometry
