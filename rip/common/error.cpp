// rip/common/error.cpp: names of rip error codes.
#include "rip/common/error.h"

namespace tp::rip {

std::string_view to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument: return "invalid_argument";
    case ErrorCode::kImage: return "image";
    case ErrorCode::kColour: return "colour";
    case ErrorCode::kScreen: return "screen";
    case ErrorCode::kSwath: return "swath";
    case ErrorCode::kIo: return "io";
    case ErrorCode::kCancelled: return "cancelled";
    case ErrorCode::kGeometry: return "geometry";
  }
  return "unknown";
}

}  // namespace tp::rip
