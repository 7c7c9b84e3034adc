// host/job/internal/field_reader.cpp: typed, self-reporting reads from a JSON manifest.
#include "host/job/internal/field_reader.h"

#include <cmath>
#include <cstdlib>

namespace tp::host::internal {

namespace {
std::string type_name(const nlohmann::json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "a boolean";
  if (v.is_number_integer() || v.is_number_unsigned()) return "an integer";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  return "an object";
}

std::string fmt_num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

std::string escape_pointer_token(const std::string& token) {
  std::string out;
  for (char c : token) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::optional<double> parse_length_text(const std::string& text, std::string& error) {
  const char* s = text.c_str();
  char* end = nullptr;
  double v = std::strtod(s, &end);
  if (end == s || !std::isfinite(v)) {
    error = "expected a length such as \"10 mm\", got \"" + text + "\"";
    return std::nullopt;
  }
  std::string unit(end);
  unit.erase(0, unit.find_first_not_of(" \t"));
  unit.erase(unit.find_last_not_of(" \t") + 1 == 0 ? 0 : unit.find_last_not_of(" \t") + 1);
  if (unit.empty() || unit == "mm") return v;
  if (unit == "cm") return v * 10.0;
  if (unit == "m") return v * 1000.0;
  if (unit == "in") return v * 25.4;
  error = "unknown unit '" + unit + "' in \"" + text + "\" (expected mm, cm, m or in)";
  return std::nullopt;
}

FieldReader::FieldReader(const nlohmann::json& obj, std::string pointer, Problems& problems)
    : obj_(obj), pointer_(std::move(pointer)), problems_(problems) {}

std::string FieldReader::pointer_of(const std::string& key) const {
  return pointer_ + "/" + escape_pointer_token(key);
}

const nlohmann::json* FieldReader::raw(const std::string& key) const {
  if (!obj_.is_object()) return nullptr;
  auto it = obj_.find(key);
  return it == obj_.end() ? nullptr : &*it;
}

const nlohmann::json* FieldReader::get(const std::string& key, bool required) {
  const nlohmann::json* v = raw(key);
  if (!v && required) problems_.add(pointer_of(key), "required field is missing");
  return v;
}

std::optional<std::string> FieldReader::string(const std::string& key, bool required) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  if (!v->is_string()) {
    problems_.add(pointer_of(key), "expected a string, got " + type_name(*v));
    return std::nullopt;
  }
  return v->get<std::string>();
}

std::optional<double> FieldReader::number(const std::string& key, bool required, double min, double max) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  if (!v->is_number()) {
    problems_.add(pointer_of(key), "expected a number, got " + type_name(*v));
    return std::nullopt;
  }
  double d = v->get<double>();
  if (!(d >= min && d <= max)) {
    problems_.add(pointer_of(key), "value " + fmt_num(d) + " is outside " + fmt_num(min) + ".." + fmt_num(max));
    return std::nullopt;
  }
  return d;
}

std::optional<int> FieldReader::integer(const std::string& key, bool required, int min, int max) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  if (!v->is_number_integer() && !v->is_number_unsigned()) {
    problems_.add(pointer_of(key), "expected an integer, got " + type_name(*v));
    return std::nullopt;
  }
  auto i = v->get<long long>();
  if (i < min || i > max) {
    problems_.add(pointer_of(key), "value " + std::to_string(i) + " is outside " + std::to_string(min) +
                                       ".." + std::to_string(max));
    return std::nullopt;
  }
  return static_cast<int>(i);
}

std::optional<bool> FieldReader::boolean(const std::string& key, bool required) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  if (!v->is_boolean()) {
    problems_.add(pointer_of(key), "expected true or false, got " + type_name(*v));
    return std::nullopt;
  }
  return v->get<bool>();
}

std::optional<double> FieldReader::parse_length(const nlohmann::json& v, const std::string& ptr) {
  if (v.is_number()) return v.get<double>();
  if (v.is_string()) {
    std::string err;
    auto mm = parse_length_text(v.get<std::string>(), err);
    if (!mm) problems_.add(ptr, err);
    return mm;
  }
  problems_.add(ptr, "expected a length (a number in mm or a string such as \"1.5 cm\"), got " + type_name(v));
  return std::nullopt;
}

std::optional<double> FieldReader::length_mm(const std::string& key, bool required, double min_mm, double max_mm) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  auto mm = parse_length(*v, pointer_of(key));
  if (!mm) return std::nullopt;
  if (!(*mm >= min_mm && *mm <= max_mm)) {
    problems_.add(pointer_of(key), "length " + fmt_num(*mm) + " mm is outside " + fmt_num(min_mm) + ".." +
                                       fmt_num(max_mm) + " mm");
    return std::nullopt;
  }
  return mm;
}

std::optional<std::string> FieldReader::choice(const std::string& key, bool required,
                                               const std::vector<std::string>& allowed) {
  auto s = string(key, required);
  if (!s) return std::nullopt;
  for (const auto& a : allowed)
    if (*s == a) return s;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  problems_.add(pointer_of(key), "unknown value \"" + *s + "\" (expected one of: " + list + ")");
  return std::nullopt;
}

template <size_t N>
std::optional<std::array<double, N>> FieldReader::vector(const std::string& key, bool required, bool lengths) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  if (!v->is_array() || v->size() != N) {
    problems_.add(pointer_of(key), "expected an array of " + std::to_string(N) + " numbers, got " + type_name(*v) +
                                       (v->is_array() ? " of " + std::to_string(v->size()) : ""));
    return std::nullopt;
  }
  std::array<double, N> out{};
  for (size_t i = 0; i < N; ++i) {
    std::string ptr = pointer_of(key) + "/" + std::to_string(i);
    const auto& e = (*v)[i];
    if (lengths) {
      auto mm = parse_length(e, ptr);
      if (!mm) return std::nullopt;
      out[i] = *mm;
    } else if (e.is_number()) {
      out[i] = e.get<double>();
    } else {
      problems_.add(ptr, "expected a number, got " + type_name(e));
      return std::nullopt;
    }
    if (!std::isfinite(out[i])) {
      problems_.add(ptr, "expected a finite number");
      return std::nullopt;
    }
  }
  return out;
}

template <size_t N>
std::optional<std::vector<std::array<double, N>>> FieldReader::vector_list(const std::string& key, bool required,
                                                                           bool lengths, size_t min_count) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  if (!v->is_array() || v->size() < min_count) {
    problems_.add(pointer_of(key), "expected an array of at least " + std::to_string(min_count) + " points of " +
                                       std::to_string(N) + " numbers, got " + type_name(*v));
    return std::nullopt;
  }
  std::vector<std::array<double, N>> out;
  for (size_t i = 0; i < v->size(); ++i) {
    // Read element i through a one-key wrapper so the pointer names the element itself.
    nlohmann::json wrap = {{std::to_string(i), (*v)[i]}};
    FieldReader r(wrap, pointer_of(key), problems_);
    auto e = r.vector<N>(std::to_string(i), true, lengths);
    if (!e) return std::nullopt;
    out.push_back(*e);
  }
  return out;
}

template std::optional<std::vector<std::array<double, 3>>> FieldReader::vector_list<3>(const std::string&, bool,
                                                                                      bool, size_t);
template std::optional<std::array<double, 2>> FieldReader::vector<2>(const std::string&, bool, bool);
template std::optional<std::array<double, 3>> FieldReader::vector<3>(const std::string&, bool, bool);
template std::optional<std::array<double, 4>> FieldReader::vector<4>(const std::string&, bool, bool);

std::optional<FieldReader> FieldReader::object(const std::string& key, bool required) {
  const nlohmann::json* v = get(key, required);
  if (!v) return std::nullopt;
  if (!v->is_object()) {
    problems_.add(pointer_of(key), "expected an object, got " + type_name(*v));
    return std::nullopt;
  }
  return FieldReader(*v, pointer_of(key), problems_);
}

std::vector<FieldReader> FieldReader::objects(const std::string& key, bool required) {
  std::vector<FieldReader> out;
  const nlohmann::json* v = get(key, required);
  if (!v) return out;
  if (!v->is_array()) {
    problems_.add(pointer_of(key), "expected an array, got " + type_name(*v));
    return out;
  }
  for (size_t i = 0; i < v->size(); ++i) {
    std::string ptr = pointer_of(key) + "/" + std::to_string(i);
    if (!(*v)[i].is_object()) {
      problems_.add(ptr, "expected an object, got " + type_name((*v)[i]));
      continue;
    }
    out.emplace_back((*v)[i], ptr, problems_);
  }
  return out;
}

void FieldReader::reject_unknown(const std::set<std::string>& known) {
  if (!obj_.is_object()) return;
  for (auto it = obj_.begin(); it != obj_.end(); ++it) {
    if (known.count(it.key())) continue;
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    problems_.add(pointer_of(it.key()), "unknown field (known here: " + list + ")");
  }
}

}  // namespace tp::host::internal
