// drivers/common/error.cpp: names of drivers error codes.
#include "drivers/common/error.h"

namespace tp::drivers {

std::string_view to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument: return "invalid_argument";
    case ErrorCode::kNotFound: return "not_found";
    case ErrorCode::kAccess: return "access";
    case ErrorCode::kBusy: return "busy";
    case ErrorCode::kIo: return "io";
    case ErrorCode::kTimeout: return "timeout";
    case ErrorCode::kStall: return "stall";
    case ErrorCode::kDisconnected: return "disconnected";
    case ErrorCode::kConfig: return "config";
  }
  return "unknown";
}

}  // namespace tp::drivers
