// tests/fuzz/geometry_xml_fuzz.cpp: the tolerant XML tokenizer on any bytes (must terminate, never crash).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/pattern/import/xml_tokenizer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  tp::geometry::XmlTokenizer tok(text);
  tp::geometry::XmlToken t;
  std::size_t tokens = 0;
  while (tok.next(t)) {
    // Every token consumes input, so there are never more tokens than bytes.
    if (++tokens > size) __builtin_trap();
  }
  return 0;
}
