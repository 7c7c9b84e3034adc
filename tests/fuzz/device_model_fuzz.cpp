// tests/fuzz/device_model_fuzz.cpp: the printer model file parser on arbitrary text. Invariant:
// whatever parses is valid and survives format -> parse unchanged.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "device/model/printer_model_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tp::device;
  auto m = parse_printer_model(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.tpm");
  if (!m) {
    if (m.error().message.rfind("fuzz.tpm", 0) != 0) std::abort();  // errors name the file
    return 0;
  }
  if (!validate_printer_model(*m)) std::abort();
  const std::string text = format_printer_model(*m);
  auto again = parse_printer_model(text, "formatted");
  if (!again || format_printer_model(*again) != text) std::abort();
  return 0;
}
