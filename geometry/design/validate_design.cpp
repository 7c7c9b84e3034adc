// geometry/design/validate_design.cpp: field-by-field checks of design layers.
#include "geometry/design/validate_design.h"

#include <cmath>
#include <string>
#include <type_traits>

namespace tp::geometry {
namespace {

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

Status bad(const std::string& where, const std::string& what) {
  return fail(ErrorCode::kDesign, where + ": " + what);
}

Status check_image(const ImageHandle& img, const std::string& where) {
  if (!img) return bad(where, "content.image is missing");
  if (img->width_px <= 0 || img->height_px <= 0)
    return bad(where, "content.image" + (img->source.empty() ? std::string() : " '" + img->source + "'") + " is empty");
  if (img->pixels.size() != static_cast<size_t>(img->width_px) * static_cast<size_t>(img->height_px))
    return bad(where, "content.image has " + std::to_string(img->pixels.size()) + " pixels for " +
                          std::to_string(img->width_px) + " x " + std::to_string(img->height_px));
  return {};
}

Status check(const CylindricalProjection& c, const std::string& w) {
  if (auto st = check_image(c.image, w); !st) return st;
  if (c.axis_origin_mm && !finite(*c.axis_origin_mm)) return bad(w, "content.axis_origin_mm must be finite");
  if (c.axis_direction && (!finite(*c.axis_direction) || norm(*c.axis_direction) == 0))
    return bad(w, "content.axis_direction must be a finite non-zero vector");
  for (auto [v, name] : {std::pair{c.radius_mm, "radius_mm"}, std::pair{c.tile_width_mm, "tile_width_mm"},
                         std::pair{c.tile_height_mm, "tile_height_mm"}})
    if (!std::isfinite(v) || v < 0) return bad(w, std::string("content.") + name + " must be >= 0");
  if (!std::isfinite(c.rotation_deg) || !finite(c.offset_mm)) return bad(w, "content.rotation_deg and offset_mm must be finite");
  return {};
}

Status check(const PlanarProjection& p, const std::string& w) {
  if (auto st = check_image(p.image, w); !st) return st;
  if (!finite(p.centre_mm)) return bad(w, "content.centre_mm must be finite");
  if (!finite(p.normal) || norm(p.normal) == 0) return bad(w, "content.normal must be a finite non-zero vector");
  if (!finite(p.up) || norm(cross(p.up, normalized(p.normal))) < 1e-6)
    return bad(w, "content.up must be finite and not parallel to content.normal");
  if (!std::isfinite(p.width_mm) || p.width_mm <= 0) return bad(w, "content.width_mm must be > 0");
  if (!std::isfinite(p.height_mm) || p.height_mm < 0) return bad(w, "content.height_mm must be >= 0");
  if (!std::isfinite(p.fade_start_deg) || !std::isfinite(p.fade_end_deg) || p.fade_start_deg < 0 ||
      p.fade_end_deg > 180 || p.fade_start_deg > p.fade_end_deg)
    return bad(w, "content.fade_start_deg and fade_end_deg must satisfy 0 <= start <= end <= 180");
  if (!std::isfinite(p.occlusion_tolerance_mm) || p.occlusion_tolerance_mm < 0)
    return bad(w, "content.occlusion_tolerance_mm must be >= 0");
  return {};
}

Status check(const BrushStroke& b, const std::string& w) {
  if (b.points_mm.empty()) return bad(w, "content.points_mm is empty");
  for (size_t i = 0; i < b.points_mm.size(); ++i)
    if (!finite(b.points_mm[i])) return bad(w, "content.points_mm[" + std::to_string(i) + "] must be finite");
  if (!std::isfinite(b.radius_mm) || b.radius_mm <= 0) return bad(w, "content.radius_mm must be > 0");
  if (!std::isfinite(b.hardness) || b.hardness < 0 || b.hardness > 1) return bad(w, "content.hardness must be in 0..1");
  return {};
}

Status check(const TextureTransfer& t, const std::string& w) {
  if (auto st = check_image(t.image, w); !st) return st;
  if (t.triangles.empty()) return bad(w, "content.triangles is empty");
  if (t.uv_triangles.size() != t.triangles.size())
    return bad(w, "content.uv_triangles has " + std::to_string(t.uv_triangles.size()) + " entries for " +
                      std::to_string(t.triangles.size()) + " triangles");
  for (size_t i = 0; i < t.vertices_mm.size(); ++i)
    if (!finite(t.vertices_mm[i])) return bad(w, "content.vertices_mm[" + std::to_string(i) + "] must be finite");
  for (size_t i = 0; i < t.uvs.size(); ++i)
    if (!finite(t.uvs[i])) return bad(w, "content.uvs[" + std::to_string(i) + "] must be finite");
  for (size_t i = 0; i < t.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int v = t.triangles[i][static_cast<size_t>(k)], u = t.uv_triangles[i][static_cast<size_t>(k)];
      if (v < 0 || static_cast<size_t>(v) >= t.vertices_mm.size())
        return bad(w, "content.triangles[" + std::to_string(i) + "] refers to vertex " + std::to_string(v));
      if (u < 0 || static_cast<size_t>(u) >= t.uvs.size())
        return bad(w, "content.uv_triangles[" + std::to_string(i) + "] refers to uv " + std::to_string(u));
    }
  if (!std::isfinite(t.max_distance_mm) || t.max_distance_mm <= 0) return bad(w, "content.max_distance_mm must be > 0");
  return {};
}

}  // namespace

Status validate_design(const Design& design) {
  if (design.layers.size() > 60000) return fail(ErrorCode::kDesign, "design: too many layers");
  for (size_t i = 0; i < design.layers.size(); ++i) {
    const DesignLayer& l = design.layers[i];
    const std::string where = "design.layers[" + std::to_string(i) + "]" + (l.name.empty() ? "" : " '" + l.name + "'");
    if (!std::isfinite(l.opacity) || l.opacity < 0 || l.opacity > 1) return bad(where, "opacity must be in 0..1");
    auto st = std::visit([&](const auto& c) { return check(c, where); }, l.content);
    if (!st) return st;
  }
  return {};
}

}  // namespace tp::geometry
