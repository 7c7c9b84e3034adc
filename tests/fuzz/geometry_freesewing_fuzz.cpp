// tests/fuzz/geometry_freesewing_fuzz.cpp: the FreeSewing SVG importer on any bytes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/pattern/import/freesewing_svg.h"
#include "geometry/pattern/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto pattern = tp::geometry::read_freesewing_svg(text, "fuzz.svg");
  if (pattern) (void)tp::geometry::find_pattern_problems(*pattern);
  return 0;
}
