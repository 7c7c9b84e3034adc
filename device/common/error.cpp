// device/common/error.cpp: names of device error codes.
#include "device/common/error.h"

namespace tp::device {

std::string_view to_string(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument: return "invalid_argument";
    case ErrorCode::kMalformedFrame: return "malformed_frame";
    case ErrorCode::kCrcMismatch: return "crc_mismatch";
    case ErrorCode::kSequenceError: return "sequence_error";
    case ErrorCode::kTimeout: return "timeout";
    case ErrorCode::kIncompatiblePrinter: return "incompatible_printer";
    case ErrorCode::kPrinterFault: return "printer_fault";
    case ErrorCode::kAborted: return "aborted";
    case ErrorCode::kTransport: return "transport";
    case ErrorCode::kBufferFull: return "buffer_full";
    case ErrorCode::kUnsupported: return "unsupported";
    case ErrorCode::kBadState: return "bad_state";
    case ErrorCode::kDisconnected: return "disconnected";
    case ErrorCode::kParse: return "parse";
  }
  return "unknown";
}

}  // namespace tp::device
