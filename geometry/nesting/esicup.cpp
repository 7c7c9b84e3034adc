// geometry/nesting/esicup.cpp: the ESICUP JSON reader, strict about types and ranges so that a
// broken instance fails with the field that is wrong.
#include "geometry/nesting/esicup.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace tp::geometry {
namespace {

using json = nlohmann::json;

// Upper bound on coordinates and counts: larger values are data errors, not garments.
constexpr double kMaxCoordinate = 1e9;
constexpr long kMaxDemand = 1000000;
constexpr size_t kMaxVertices = 1000000;

class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  std::unexpected<Error> error(const std::string& pointer, const std::string& what) const {
    return fail(ErrorCode::kParse, source_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
  }

  Result<double> number(const json& j, const std::string& ptr, bool positive) const {
    if (!j.is_number()) return error(ptr, "expected a number");
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::fabs(v) > kMaxCoordinate) return error(ptr, "number out of range");
    if (positive && !(v > 0)) return error(ptr, "must be greater than 0");
    return v;
  }

  Result<Polygon> ring(const json& j, const std::string& ptr) const {
    if (!j.is_array()) return error(ptr, "expected an array of [x, y] points");
    if (j.size() > kMaxVertices) return error(ptr, "too many vertices");
    Polygon p;
    for (size_t i = 0; i < j.size(); ++i) {
      const std::string pp = ptr + "/" + std::to_string(i);
      const json& v = j[i];
      if (!v.is_array() || v.size() != 2) return error(pp, "expected a point [x, y]");
      auto x = number(v[0], pp + "/0", false);
      if (!x) return std::unexpected(x.error());
      auto y = number(v[1], pp + "/1", false);
      if (!y) return std::unexpected(y.error());
      p.push_back({*x, *y});
    }
    // Instances often repeat the first point at the end.
    if (p.size() > 1 && p.front() == p.back()) p.pop_back();
    if (p.size() < 3) return error(ptr, "a polygon needs at least 3 distinct points");
    return p;
  }

  Result<Polygon> shape(const json& j, const std::string& ptr) const {
    if (!j.is_object()) return error(ptr, "expected an object with 'type' and 'data'");
    if (!j.contains("type") || !j["type"].is_string()) return error(ptr + "/type", "expected a string");
    if (!j.contains("data")) return error(ptr + "/data", "missing");
    const std::string type = j["type"].get<std::string>();
    const json& d = j["data"];
    if (type == "simple_polygon") return ring(d, ptr + "/data");
    if (type == "polygon") {
      if (!d.is_object() || !d.contains("outer")) return error(ptr + "/data/outer", "missing");
      return ring(d["outer"], ptr + "/data/outer");
    }
    if (type == "rectangle") {
      if (!d.is_object()) return error(ptr + "/data", "expected {x_min, y_min, width, height}");
      double v[4];
      const char* keys[] = {"x_min", "y_min", "width", "height"};
      for (int k = 0; k < 4; ++k) {
        if (!d.contains(keys[k])) return error(ptr + "/data/" + keys[k], "missing");
        auto x = number(d[keys[k]], ptr + "/data/" + keys[k], k >= 2);
        if (!x) return std::unexpected(x.error());
        v[k] = *x;
      }
      return Polygon{{v[0], v[1]}, {v[0] + v[2], v[1]}, {v[0] + v[2], v[1] + v[3]}, {v[0], v[1] + v[3]}};
    }
    return error(ptr + "/type", "unsupported shape type '" + type + "'");
  }

  Result<StripItem> item(const json& j, const std::string& ptr) const {
    if (!j.is_object()) return error(ptr, "expected an object");
    StripItem it;
    if (!j.contains("id") || !j["id"].is_number_integer()) return error(ptr + "/id", "expected an integer");
    const long id = j["id"].get<long>();
    if (id < 0 || id > 1000000000) return error(ptr + "/id", "out of range");
    it.id = static_cast<int>(id);
    if (!j.contains("demand") || !j["demand"].is_number_integer()) return error(ptr + "/demand", "expected an integer");
    const long demand = j["demand"].get<long>();
    if (demand < 0 || demand > kMaxDemand) return error(ptr + "/demand", "out of range");
    it.demand = static_cast<int>(demand);
    it.poses.clear();
    if (j.contains("allowed_orientations") && !j["allowed_orientations"].is_null()) {
      const json& o = j["allowed_orientations"];
      if (!o.is_array() || o.empty()) return error(ptr + "/allowed_orientations", "expected a non-empty array of degrees");
      for (size_t i = 0; i < o.size(); ++i) {
        auto deg = number(o[i], ptr + "/allowed_orientations/" + std::to_string(i), false);
        if (!deg) return std::unexpected(deg.error());
        it.poses.push_back({*deg, false});
      }
    } else {
      it.poses.push_back({0.0, false});
    }
    if (!j.contains("shape")) return error(ptr + "/shape", "missing");
    auto s = shape(j["shape"], ptr + "/shape");
    if (!s) return std::unexpected(s.error());
    it.shape = std::move(*s);
    return it;
  }

  Result<StripProblem> problem(const json& j) const {
    if (!j.is_object()) return error("", "expected an object");
    StripProblem p;
    if (j.contains("name")) {
      if (!j["name"].is_string()) return error("/name", "expected a string");
      p.name = j["name"].get<std::string>();
    }
    if (!j.contains("strip_height")) return error("/strip_height", "missing");
    auto w = number(j["strip_height"], "/strip_height", true);
    if (!w) return std::unexpected(w.error());
    p.width = *w;
    if (!j.contains("items") || !j["items"].is_array()) return error("/items", "expected an array");
    if (j["items"].empty()) return error("/items", "no items");
    for (size_t i = 0; i < j["items"].size(); ++i) {
      auto it = item(j["items"][i], "/items/" + std::to_string(i));
      if (!it) return std::unexpected(it.error());
      p.items.push_back(std::move(*it));
    }
    return p;
  }

 private:
  std::string source_;
};

}  // namespace

Result<StripProblem> parse_esicup(std::string_view json_text, std::string_view source) {
  const Reader reader(source);
  json j;
  try {
    j = json::parse(json_text.begin(), json_text.end());
  } catch (const json::parse_error& e) {
    return fail(ErrorCode::kParse, std::string(source) + ": not valid JSON (byte " + std::to_string(e.byte) + ")");
  } catch (const json::exception&) {
    return fail(ErrorCode::kParse, std::string(source) + ": not valid JSON (a number out of range)");
  }
  auto p = reader.problem(j);
  if (p && p->name.empty()) p->name = std::filesystem::path(source).stem().string();
  return p;
}

Result<StripProblem> load_esicup(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, file.string() + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return fail(ErrorCode::kIo, file.string() + ": read failed");
  return parse_esicup(text.str(), file.string());
}

}  // namespace tp::geometry
