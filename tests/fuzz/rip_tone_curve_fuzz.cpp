// tests/fuzz/rip_tone_curve_fuzz.cpp: fuzzes the linearisation curve parser; accepted curves must
// evaluate monotonically inside 0..1.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "rip/colour/tone_curve.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto curve = tp::rip::parse_tone_curve(text, "fuzz curve");
  if (!curve) return 0;
  double prev = -1;
  for (int i = 0; i <= 64; ++i) {
    const double y = tp::rip::evaluate(*curve, i / 64.0);
    if (!(y >= 0 && y <= 1) || y < prev) std::abort();  // a parsed curve must stay monotone in range
    prev = y;
  }
  return 0;
}
