// tests/fuzz/geometry_dxf_aama_fuzz.cpp: the DXF-AAMA importer on any bytes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/pattern/import/dxf_aama.h"
#include "geometry/pattern/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto pattern = tp::geometry::read_dxf_aama(text, "fuzz.dxf");
  if (pattern) (void)tp::geometry::find_pattern_problems(*pattern);
  return 0;
}
