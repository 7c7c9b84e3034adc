// tests/fuzz/geometry_pattern_json_fuzz.cpp: the native JSON pattern reader, validation and writer on any bytes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/pattern/pattern_json.h"
#include "geometry/pattern/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto pattern = tp::geometry::read_pattern_json(text, "fuzz.json");
  if (!pattern) return 0;
  (void)tp::geometry::find_pattern_problems(*pattern);
  // What the writer produces must read back.
  std::string again = tp::geometry::write_pattern_json(*pattern);
  auto reread = tp::geometry::read_pattern_json(again, "rewritten.json");
  if (!reread) __builtin_trap();
  return 0;
}
