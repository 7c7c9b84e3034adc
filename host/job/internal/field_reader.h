// host/job/internal/field_reader.h: typed reads from a JSON manifest that record every problem
// with the file name and a JSON pointer to the field ("job.json: /print/dpi: expected an integer").
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tp::host::internal {

/// Collects validation problems for one manifest file.
class Problems {
 public:
  explicit Problems(std::string file) : file_(std::move(file)) {}
  void add(const std::string& pointer, const std::string& what) {
    items_.push_back(file_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
  }
  bool empty() const { return items_.empty(); }
  const std::vector<std::string>& items() const { return items_; }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::vector<std::string> items_;
};

/// A view of one JSON object at a pointer, with typed getters that report problems.
class FieldReader {
 public:
  FieldReader(const nlohmann::json& obj, std::string pointer, Problems& problems);

  /// True when the value at this pointer is an object (else a problem is recorded).
  bool is_object() const { return obj_.is_object(); }
  bool has(const std::string& key) const { return obj_.is_object() && obj_.contains(key); }
  std::string pointer_of(const std::string& key) const;

  std::optional<std::string> string(const std::string& key, bool required);
  std::optional<double> number(const std::string& key, bool required, double min, double max);
  std::optional<int> integer(const std::string& key, bool required, int min, int max);
  std::optional<bool> boolean(const std::string& key, bool required);
  /// A length: a number (mm) or a string "<number> <unit>" with unit mm, cm, m or in.
  std::optional<double> length_mm(const std::string& key, bool required, double min_mm, double max_mm);
  /// A string that must be one of `allowed`.
  std::optional<std::string> choice(const std::string& key, bool required,
                                    const std::vector<std::string>& allowed);
  /// An array of exactly N numbers (optionally lengths with units).
  template <size_t N>
  std::optional<std::array<double, N>> vector(const std::string& key, bool required, bool lengths);
  /// An array of arrays of N numbers each (e.g. a polyline of 3D points).
  template <size_t N>
  std::optional<std::vector<std::array<double, N>>> vector_list(const std::string& key, bool required,
                                                                bool lengths, size_t min_count);
  std::optional<FieldReader> object(const std::string& key, bool required);
  /// Elements of an array field as readers (non-objects are reported).
  std::vector<FieldReader> objects(const std::string& key, bool required);
  const nlohmann::json* raw(const std::string& key) const;

  /// Reports keys not in `known` (typos must not pass silently).
  void reject_unknown(const std::set<std::string>& known);
  Problems& problems() { return problems_; }
  const std::string& pointer() const { return pointer_; }

 private:
  const nlohmann::json* get(const std::string& key, bool required);
  std::optional<double> parse_length(const nlohmann::json& v, const std::string& ptr);

  const nlohmann::json& obj_;
  std::string pointer_;
  Problems& problems_;
};

/// JSON pointer escaping of one reference token (~ and /).
std::string escape_pointer_token(const std::string& token);

/// Converts "<number> <unit>" to mm; nullopt with `error` set when the unit is unknown.
std::optional<double> parse_length_text(const std::string& text, std::string& error);

}  // namespace tp::host::internal
