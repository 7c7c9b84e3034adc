// tests/fuzz/geometry_obj_garment_fuzz.cpp: the OBJ garment importer (UV islands, seams) on any bytes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/pattern/import/obj_garment.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto g = tp::geometry::read_obj_garment(text, "fuzz.obj");
  if (!g) return 0;
  // Every chart vertex must name an existing 3D vertex.
  for (const auto& piece : g->garment.pieces)
    for (int v : piece.vertex_3d)
      if (v < 0 || v >= static_cast<int>(g->garment.vertices_mm.size())) __builtin_trap();
  return 0;
}
