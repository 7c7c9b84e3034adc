// simulator/common/error.cpp: names of simulator error codes.
#include "simulator/common/error.h"

namespace tp::sim {

std::string_view to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument: return "invalid_argument";
    case ErrorCode::kTestbed: return "testbed";
    case ErrorCode::kScenario: return "scenario";
    case ErrorCode::kIo: return "io";
    case ErrorCode::kChild: return "child";
    case ErrorCode::kUsb: return "usb";
    case ErrorCode::kOutput: return "output";
  }
  return "unknown";
}

}  // namespace tp::sim
