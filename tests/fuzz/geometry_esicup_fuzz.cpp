// tests/fuzz/geometry_esicup_fuzz.cpp: fuzzes the ESICUP instance reader, and nests what it
// accepts when the instance is small (constructive placement only, so each input stays fast).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/nesting/esicup.h"
#include "geometry/nesting/strip_nester.h"

namespace {

// Instances up to this size are nested too.
constexpr int kMaxCopies = 6;
constexpr size_t kMaxVertices = 24;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto problem = tp::geometry::parse_esicup(text, "fuzz.json");
  if (!problem) return 0;
  int copies = 0;
  for (const auto& it : problem->items) {
    copies += it.demand;
    if (it.shape.size() > kMaxVertices) return 0;
  }
  if (copies > kMaxCopies) return 0;
  tp::geometry::StripOptions o;
  o.improve = false;
  auto solved = tp::geometry::nest_strip(*problem, o);
  if (solved && solved->placements.size() + solved->unplaced.size() != static_cast<size_t>(copies)) __builtin_trap();
  return 0;
}
