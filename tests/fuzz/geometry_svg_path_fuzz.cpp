// tests/fuzz/geometry_svg_path_fuzz.cpp: SVG path data and transform parsing, arcs to cubics, on any bytes.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/pattern/import/svg_path.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto paths = tp::geometry::parse_svg_path(text);
  if (paths) {
    for (const auto& sp : *paths)
      for (const auto& seg : sp.segments)
        if (seg.kind == tp::geometry::SvgSegment::Kind::kArc) {
          auto cubics = tp::geometry::svg_arc_to_cubics(seg, 0.01);
          if (cubics.size() > 1024) __builtin_trap();
        }
  }
  (void)tp::geometry::parse_svg_transform(text);
  return 0;
}
