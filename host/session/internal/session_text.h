// host/session/internal/session_text.h: the print session's error and length wording, shared by
// its source files.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "device/common/error.h"
#include "host/common/error.h"

namespace tp::host::internal {

/// A device-layer error as a printer error of the host, with `context` before its message.
inline Error from_device(const device::Error& e, const std::string& context) {
  return Error{ErrorCode::kPrinter, context + ": " + e.message};
}

/// A fabric position in micrometres as "123.4 mm".
inline std::string mm_text(std::int64_t um) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f mm", static_cast<double>(um) / 1000.0);
  return b;
}

}  // namespace tp::host::internal
