// simulator/common/error.h: error codes, context-carrying errors and Result<T> for simulator/.
#pragma once

#include <expected>
#if !defined(__cpp_lib_expected)
#include "expected_polyfill.h"  // clang 14 fuzz build only (tests/fuzz/compat)
#endif
#include <string>
#include <string_view>
#include <utility>

namespace tp::sim {

/// What went wrong in simulator/ code.
enum class ErrorCode {
  kInvalidArgument,
  kTestbed,
  kScenario,
  kIo,
  kChild,
  kUsb,
  kOutput,
};

/// Short stable name of a code, for logs and reports.
std::string_view to_string(ErrorCode code);

/// An error whose message names what failed (file, piece, field, swath...).
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

/// Shorthand for returning a failure.
[[nodiscard]] inline std::unexpected<Error> fail(ErrorCode code, std::string message) {
  return std::unexpected(Error{code, std::move(message)});
}

/// Returns an existing error (e.g. one given context) as a failure: `return fail(e.with_context(..));`.
[[nodiscard]] inline std::unexpected<Error> fail(Error error) { return std::unexpected(std::move(error)); }

}  // namespace tp::sim
