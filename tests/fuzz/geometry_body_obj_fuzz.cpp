// tests/fuzz/geometry_body_obj_fuzz.cpp: fuzzes the body OBJ reader and the measurement text parser,
// and builds the body SDF of small accepted meshes (so each input stays fast).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/body/body_sdf.h"
#include "geometry/body/load_body_obj.h"
#include "geometry/body/measurements.h"

namespace {

// Meshes up to this size (triangles, extent in mm) get an SDF and a few queries.
constexpr size_t kMaxTriangles = 64;
constexpr double kMaxExtentMm = 200;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  (void)tp::geometry::parse_measurements(text, tp::geometry::BodyMeasurements{});
  auto mesh = tp::geometry::parse_body_obj(text, 1, "fuzz.obj");
  if (!mesh || mesh->triangles.size() > kMaxTriangles) return 0;
  tp::geometry::Box3 b = tp::geometry::bounds(*mesh);
  for (double e : {b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z})
    if (!(e <= kMaxExtentMm)) return 0;
  auto sdf = tp::geometry::BodySdf::build(std::move(*mesh), 10, 2);
  if (!sdf) return 0;
  for (const auto& v : sdf->mesh().vertices_mm) (void)sdf->query(v + tp::geometry::Vec3{1, 2, 3});
  return 0;
}
