// geometry/design/sample_designs.cpp: marbling, motif and stroke designs for the sample garments.
#include "geometry/design/sample_designs.h"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "geometry/design/fit_cylinder.h"
#include "geometry/design/internal/closest_point.h"
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

// Points on the garment seen from the axis: the ray from the axis at height h in direction
// theta, where it meets the garment (points it misses are left out).
std::vector<Vec3> on_garment(const internal::ClosestPointIndex& index, const Cylinder& cyl, const std::vector<std::array<double, 2>>& h_theta) {
  const Vec3 a = cyl.direction;
  const Vec3 front{0, 0, 1}, side = normalized(cross(a, front));
  std::vector<Vec3> out;
  for (const auto& [h, th] : h_theta) {
    const internal::MeshHit hit = index.first_hit(cyl.origin_mm + a * h, front * std::cos(th) + side * std::sin(th));
    if (hit.triangle >= 0) out.push_back(hit.point_mm);
  }
  return out;
}

// Splits a stroke where the garment seen from the axis jumps (an armhole, a dart's fold): the
// brush lifts there instead of painting across.
std::vector<std::vector<Vec3>> lift_at_jumps(const std::vector<Vec3>& pts, double max_step_mm) {
  std::vector<std::vector<Vec3>> out(1);
  for (size_t i = 0; i < pts.size(); ++i) {
    if (i > 0 && norm(pts[i] - pts[i - 1]) > max_step_mm) out.emplace_back();
    out.back().push_back(pts[i]);
  }
  // A closed ring lifted somewhere: its last part runs on into its first.
  if (out.size() > 1 && norm(out.back().back() - out.front().front()) <= max_step_mm) {
    out.back().insert(out.back().end(), out.front().begin() + 1, out.front().end());
    out.erase(out.begin());
  }
  return out;
}

std::vector<DesignLayer> stroke_layers(const Garment& garment, const Cylinder& cyl) {
  std::vector<DesignLayer> out;
  std::vector<std::array<int, 3>> tris;
  for (const GarmentPiece& gp : garment.pieces)
    for (const auto& t : gp.mesh.triangles)
      tris.push_back({gp.vertex_3d[static_cast<size_t>(t[0])], gp.vertex_3d[static_cast<size_t>(t[1])], gp.vertex_3d[static_cast<size_t>(t[2])]});
  const internal::ClosestPointIndex index(garment.vertices_mm, tris);
  const double pi = std::numbers::pi;
  const double h0 = cyl.min_height_mm, h1 = cyl.max_height_mm;
  const Rgba8 colours[] = {{30, 60, 150, 255}, {200, 60, 40, 255}, {40, 140, 90, 255}, {230, 170, 30, 255}};
  // Rings around the body at constant height, each point where the garment is seen from the axis.
  for (int i = 0; i < 4; ++i) {
    BrushStroke b;
    const double h = h0 + (h1 - h0) * (0.2 + 0.18 * i);
    std::vector<std::array<double, 2>> ring;
    for (int k = 0; k <= 180; ++k) ring.push_back({h, 2 * pi * k / 180});
    b.radius_mm = 6 + 2 * i;
    b.hardness = 0.6;
    b.colour = colours[i];
    // Neighbouring ring points are 2 degrees apart: a few times that on the garment is a jump.
    int part = 0;
    for (auto& pts : lift_at_jumps(on_garment(index, cyl, ring), 6 * cyl.radius_mm * 2 * pi / 180)) {
      if (pts.size() < 2) continue;
      b.points_mm = std::move(pts);
      out.push_back({"ring " + std::to_string(i + 1) + "." + std::to_string(++part), 0.9, b});
    }
  }
  // A diagonal sweep across the front and round both sides.
  BrushStroke sweep;
  std::vector<std::array<double, 2>> path;
  for (int k = 0; k <= 128; ++k) {
    const double t = static_cast<double>(k) / 128;
    path.push_back({h0 + (h1 - h0) * (0.85 - 0.6 * t), -0.6 * pi + 1.2 * pi * t});
  }
  const auto parts = lift_at_jumps(on_garment(index, cyl, path), 6 * cyl.radius_mm * 1.2 * pi / 128);
  sweep.radius_mm = 12;
  sweep.hardness = 0.3;
  sweep.colour = {120, 40, 140, 255};
  for (const auto& pts : parts) {
    if (pts.size() < 2) continue;
    sweep.points_mm = pts;
    out.push_back({"sweep", 0.8, sweep});
  }
  return out;
}

}  // namespace

Design sample_design(std::string_view name, const Garment& garment) {
  const Cylinder cyl = fit_cylinder(garment.vertices_mm, {0, 1, 0});
  Design d;
  if (name == "simple_top") {
    d.layers = stroke_layers(garment, cyl);
    return d;
  }
  d.layers.push_back(marbling_layer(cyl));
  if (name == "dress" || name == "blouse") d.layers.push_back(motif_layer(cyl));
  return d;
}

}  // namespace tp::geometry
