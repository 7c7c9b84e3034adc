// geometry/body/load_body_obj.cpp: a body mesh from an OBJ file (geometry/mesh/read_obj), scaled to mm.
#include "geometry/body/load_body_obj.h"

#include <fstream>
#include <sstream>

#include "geometry/mesh/read_obj.h"

namespace tp::geometry {

Result<BodyMesh> parse_body_obj(std::string_view text, double mm_per_unit, const std::string& source) {
  if (!(mm_per_unit > 0)) return fail(ErrorCode::kInvalidArgument, source + ": units scale must be > 0");
  auto obj_r = read_obj(text, source);
  if (!obj_r) return fail(obj_r.error());
  const ObjMesh& obj = *obj_r;
  if (obj.triangles.empty()) return fail(ErrorCode::kParse, source + ": no faces");
  BodyMesh mesh;
  mesh.name = source;
  mesh.vertices_mm.reserve(obj.positions.size());
  for (const Vec3& p : obj.positions) mesh.vertices_mm.push_back(p * mm_per_unit);
  mesh.triangles.reserve(obj.triangles.size());
  for (const ObjTriangle& t : obj.triangles) mesh.triangles.push_back({t.c[0].v, t.c[1].v, t.c[2].v});
  return mesh;
}

Result<BodyMesh> load_body_obj(const std::string& path, double mm_per_unit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, path + ": cannot open");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_body_obj(ss.str(), mm_per_unit, path);
}

}  // namespace tp::geometry
