// geometry/design/texture_model.cpp: a textured OBJ to the triangles of a TextureTransfer layer.
#include "geometry/design/texture_model.h"

#include <cmath>

#include "geometry/mesh/read_obj.h"
#include "geometry/pattern/internal/read_file.h"

namespace tp::geometry {

Result<TextureTransfer> read_texture_model(std::string_view obj_text, const std::string& source_name,
                                           double mm_per_unit) {
  if (!std::isfinite(mm_per_unit) || mm_per_unit <= 0)
    return fail(ErrorCode::kDesign, source_name + ": units scale must be positive");
  auto mesh = read_obj(obj_text, source_name, {.require_texture_coordinates = true});
  if (!mesh) return fail(mesh.error());
  if (mesh->triangles.empty()) return fail(ErrorCode::kDesign, source_name + ": the textured model has no faces");
  TextureTransfer t;
  t.vertices_mm.reserve(mesh->positions.size());
  Vec3 lo = mesh->positions.front() * mm_per_unit, hi = lo;
  for (const Vec3& p : mesh->positions) {
    const Vec3 q = p * mm_per_unit;
    t.vertices_mm.push_back(q);
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
  }
  if (norm(hi - lo) < 1.0)
    return fail(ErrorCode::kDesign, source_name + ": the textured model spans less than 1 mm; are its units right?");
  t.uvs = mesh->uvs;
  t.triangles.reserve(mesh->triangles.size());
  t.uv_triangles.reserve(mesh->triangles.size());
  for (const auto& tri : mesh->triangles) {
    t.triangles.push_back({tri.c[0].v, tri.c[1].v, tri.c[2].v});
    t.uv_triangles.push_back({tri.c[0].vt, tri.c[1].vt, tri.c[2].vt});
  }
  return t;
}

Result<TextureTransfer> load_texture_model(const std::filesystem::path& path, double mm_per_unit) {
  auto text = internal::read_file(path);
  if (!text) return fail(text.error());
  return read_texture_model(*text, path.string(), mm_per_unit);
}

}  // namespace tp::geometry
