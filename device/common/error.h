// device/common/error.h: error codes, context-carrying errors and Result<T> for device/.
#pragma once

#include <expected>
#if !defined(__cpp_lib_expected)
#include "expected_polyfill.h"  // clang 14 fuzz build only (tests/fuzz/compat)
#endif
#include <string>
#include <string_view>
#include <utility>

namespace tp::device {

/// What went wrong in device/ code (protocol, firmware, printer model).
enum class ErrorCode {
  kInvalidArgument,
  kMalformedFrame,
  kCrcMismatch,
  kSequenceError,
  kTimeout,
  kIncompatiblePrinter,
  kPrinterFault,
  kAborted,
  kTransport,
  kBufferFull,
  kUnsupported,
  kBadState,
  kDisconnected,
  kParse,
};

/// Short stable name of a code ("crc_mismatch"), for logs and reports.
std::string_view to_string(ErrorCode code);

/// An error with a message that names what failed ("swath 12: chunk 3: CRC mismatch").
struct Error {
  ErrorCode code = ErrorCode::kInvalidArgument;
  std::string message;

  /// The same error with `context` prepended: "context: message".
  [[nodiscard]] Error with_context(std::string_view context) const {
    return Error{code, std::string(context) + ": " + message};
  }
  /// "message (code)" for people.
  [[nodiscard]] std::string what() const { return message + " (" + std::string(to_string(code)) + ")"; }
};

template <class T>
using Result = std::expected<T, Error>;
using Status = std::expected<void, Error>;

/// Shorthand for returning a failure: `return fail(ErrorCode::kTimeout, "no ack");`.
[[nodiscard]] inline std::unexpected<Error> fail(ErrorCode code, std::string message) {
  return std::unexpected(Error{code, std::move(message)});
}

/// Returns an existing error (e.g. one given context) as a failure: `return fail(e.with_context(..));`.
[[nodiscard]] inline std::unexpected<Error> fail(Error error) { return std::unexpected(std::move(error)); }

}  // namespace tp::device
