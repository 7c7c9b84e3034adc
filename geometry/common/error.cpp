// geometry/common/error.cpp: names of geometry error codes.
#include "geometry/common/error.h"

namespace tp::geometry {

std::string_view to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument: return "invalid_argument";
    case ErrorCode::kParse: return "parse";
    case ErrorCode::kInvalidPattern: return "invalid_pattern";
    case ErrorCode::kUnknownReference: return "unknown_reference";
    case ErrorCode::kMeshing: return "meshing";
    case ErrorCode::kSewing: return "sewing";
    case ErrorCode::kNesting: return "nesting";
    case ErrorCode::kDesign: return "design";
    case ErrorCode::kAllowance: return "allowance";
    case ErrorCode::kIo: return "io";
    case ErrorCode::kCancelled: return "cancelled";
  }
  return "unknown";
}

}  // namespace tp::geometry
