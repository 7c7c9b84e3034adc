// geometry/pattern/internal/text.h: number formatting for pattern messages (no <format> on g++ 12).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// "12.35" (two decimals: a hundredth of a millimetre is below any cutter's resolution).
inline std::string mm(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

/// "(12.35, -4.00)".
inline std::string point(Vec2 p) { return "(" + mm(p.x) + ", " + mm(p.y) + ")"; }

/// Shortest round-trip text of a double ("0.1", "1e-07"), for files that are read back.
inline std::string exact(double v) {
  char buf[64];
  for (int prec = 6; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

}  // namespace tp::geometry::internal
