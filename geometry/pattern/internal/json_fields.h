// geometry/pattern/internal/json_fields.h: typed access to JSON values with errors naming file and pointer.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/common/vec.h"

namespace tp::geometry::internal {

/// Where a JSON value sits: the file (or source name) and its JSON pointer.
struct JsonPath {
  std::string file;
  std::string pointer;  ///< "" for the document root

  JsonPath operator/(std::string_view key) const;
  JsonPath operator/(size_t index) const;
  /// "file: /pieces/0/name: message".
  Error error(ErrorCode code, const std::string& message) const;
};

/// The member `key` of object `obj`, or nullptr when absent (or obj is not an object).
const nlohmann::json* member(const nlohmann::json& obj, std::string_view key);

/// A finite number.
[[nodiscard]] Result<double> get_number(const nlohmann::json& v, const JsonPath& at);
/// An integer within [lo, hi].
[[nodiscard]] Result<long long> get_integer(const nlohmann::json& v, const JsonPath& at, long long lo, long long hi);
/// A string.
[[nodiscard]] Result<std::string> get_string(const nlohmann::json& v, const JsonPath& at);
/// A boolean (true/false, or 0/1).
[[nodiscard]] Result<bool> get_bool(const nlohmann::json& v, const JsonPath& at);
/// [x, y] of finite numbers, each multiplied by `scale`.
[[nodiscard]] Result<Vec2> get_point(const nlohmann::json& v, const JsonPath& at, double scale = 1);
/// An array (possibly empty).
[[nodiscard]] Status expect_array(const nlohmann::json& v, const JsonPath& at);
/// An object.
[[nodiscard]] Status expect_object(const nlohmann::json& v, const JsonPath& at);

/// Parses `text`; a syntax error names the file, line and column.
[[nodiscard]] Result<nlohmann::json> parse_json(std::string_view text, const std::string& file);

}  // namespace tp::geometry::internal
