// geometry/pattern/internal/json_fields.cpp: JSON access helpers for the pattern importers.
#include "geometry/pattern/internal/json_fields.h"

#include <algorithm>
#include <cmath>

namespace tp::geometry::internal {

using nlohmann::json;

JsonPath JsonPath::operator/(std::string_view key) const {
  // RFC 6901 escaping so a key holding '/' or '~' still names one member.
  std::string esc;
  for (char c : key) {
    if (c == '~') esc += "~0";
    else if (c == '/') esc += "~1";
    else esc += c;
  }
  return JsonPath{file, pointer + "/" + esc};
}

JsonPath JsonPath::operator/(size_t index) const { return JsonPath{file, pointer + "/" + std::to_string(index)}; }

Error JsonPath::error(ErrorCode code, const std::string& message) const {
  return Error{code, file + ": " + (pointer.empty() ? std::string("/") : pointer) + ": " + message};
}

const json* member(const json& obj, std::string_view key) {
  if (!obj.is_object()) return nullptr;
  auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

namespace {
std::string type_of(const json& v) { return v.type_name(); }
}  // namespace

Result<double> get_number(const json& v, const JsonPath& at) {
  if (!v.is_number()) return std::unexpected(at.error(ErrorCode::kParse, "expected a number, found " + type_of(v)));
  double d = v.get<double>();
  if (!std::isfinite(d)) return std::unexpected(at.error(ErrorCode::kParse, "number is not finite"));
  return d;
}

Result<long long> get_integer(const json& v, const JsonPath& at, long long lo, long long hi) {
  if (!v.is_number_integer() && !(v.is_number_float() && std::floor(v.get<double>()) == v.get<double>()))
    return std::unexpected(at.error(ErrorCode::kParse, "expected an integer, found " + type_of(v)));
  double d = v.get<double>();
  if (!(d >= static_cast<double>(lo) && d <= static_cast<double>(hi)))
    return std::unexpected(at.error(ErrorCode::kParse, "integer out of range [" + std::to_string(lo) + ", " +
                                                           std::to_string(hi) + "]"));
  return static_cast<long long>(d);
}

Result<std::string> get_string(const json& v, const JsonPath& at) {
  if (!v.is_string()) return std::unexpected(at.error(ErrorCode::kParse, "expected a string, found " + type_of(v)));
  return v.get<std::string>();
}

Result<bool> get_bool(const json& v, const JsonPath& at) {
  if (v.is_boolean()) return v.get<bool>();
  if (v.is_number_integer() && (v.get<long long>() == 0 || v.get<long long>() == 1)) return v.get<long long>() == 1;
  return std::unexpected(at.error(ErrorCode::kParse, "expected true or false, found " + type_of(v)));
}

Result<Vec2> get_point(const json& v, const JsonPath& at, double scale) {
  if (!v.is_array() || v.size() != 2)
    return std::unexpected(at.error(ErrorCode::kParse, "expected a point [x, y], found " +
                                                           (v.is_array() ? "an array of " + std::to_string(v.size())
                                                                         : type_of(v))));
  auto x = get_number(v[0], at / 0);
  if (!x) return std::unexpected(x.error());
  auto y = get_number(v[1], at / 1);
  if (!y) return std::unexpected(y.error());
  Vec2 p{*x * scale, *y * scale};
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    return std::unexpected(at.error(ErrorCode::kParse, "point is out of range"));
  return p;
}

Status expect_array(const json& v, const JsonPath& at) {
  if (!v.is_array()) return std::unexpected(at.error(ErrorCode::kParse, "expected an array, found " + type_of(v)));
  return {};
}

Status expect_object(const json& v, const JsonPath& at) {
  if (!v.is_object()) return std::unexpected(at.error(ErrorCode::kParse, "expected an object, found " + type_of(v)));
  return {};
}

Result<json> parse_json(std::string_view text, const std::string& file) {
  // Deep nesting would only exhaust the stack of json's recursive parts; no pattern needs it.
  constexpr int kMaxDepth = 128;
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxDepth)
        return fail(ErrorCode::kParse, file + ": JSON nested deeper than " + std::to_string(kMaxDepth) + " levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // Turn the byte offset into line:column, which an editor can jump to.
    size_t off = std::min<size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    size_t line = 1, col = 1;
    for (size_t i = 0; i < off; ++i) {
      if (text[i] == '\n') { ++line; col = 1; } else { ++col; }
    }
    std::string what = e.what();
    auto pos = what.find("syntax error");
    if (pos != std::string::npos) what = what.substr(pos);
    return fail(ErrorCode::kParse, file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": not valid JSON: " + what);
  } catch (const json::exception& e) {
    // Numbers out of range and invalid UTF-8 in strings are reported without a position.
    std::string what = e.what();
    auto pos = what.find("] ");
    return fail(ErrorCode::kParse, file + ": not valid JSON: " + (pos == std::string::npos ? what : what.substr(pos + 2)));
  }
}

}  // namespace tp::geometry::internal
