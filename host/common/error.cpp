// host/common/error.cpp: names of host error codes.
#include "host/common/error.h"

namespace tp::host {

std::string_view to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument: return "invalid_argument";
    case ErrorCode::kJob: return "job";
    case ErrorCode::kValidation: return "validation";
    case ErrorCode::kUnsafePath: return "unsafe_path";
    case ErrorCode::kArchive: return "archive";
    case ErrorCode::kStore: return "store";
    case ErrorCode::kPipeline: return "pipeline";
    case ErrorCode::kPrinter: return "printer";
    case ErrorCode::kCancelled: return "cancelled";
    case ErrorCode::kIo: return "io";
    case ErrorCode::kDaemon: return "daemon";
  }
  return "unknown";
}

}  // namespace tp::host
