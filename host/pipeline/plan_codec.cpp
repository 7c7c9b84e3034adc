// host/pipeline/plan_codec.cpp: lossless text files of a stored plan (see internal/plan_codec.h).
#include "host/pipeline/internal/plan_codec.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>

#include "host/pipeline/internal/input_hash.h"

namespace tp::host::internal {

namespace {

constexpr const char* kGarmentFormat = "tp-garment-plan/1";
constexpr const char* kMarkerFormat = "tp-marker-plan/1";
constexpr const char* kSwathFormat = "tp-swath-plan/1";

// %.17g round-trips every finite double through strtod.
void put(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  out += buf;
}

// Reads the garment file line by line, numbers by strtod/strtoll, naming the line on errors.
class LineReader {
 public:
  LineReader(const std::string& text, const std::string& where) : in_(text), where_(where) {}

  bool next() {
    if (!std::getline(in_, line_)) return false;
    ++line_no_;
    pos_ = line_.c_str();
    return true;
  }
  Error error(const std::string& what) const {
    return Error{ErrorCode::kPipeline, where_ + ": line " + std::to_string(line_no_) + ": " + what};
  }
  const std::string& line() const { return line_; }
  bool word(const char* w) {
    while (*pos_ == ' ') ++pos_;
    const std::size_t n = std::strlen(w);
    if (std::strncmp(pos_, w, n) != 0 || (pos_[n] != ' ' && pos_[n] != 0)) return false;
    pos_ += n;
    return true;
  }
  bool number(double& v) {
    char* end = nullptr;
    errno = 0;
    v = std::strtod(pos_, &end);
    if (end == pos_ || errno == ERANGE || !std::isfinite(v)) return false;
    pos_ = end;
    return true;
  }
  bool integer(long long& v, long long lo, long long hi) {
    char* end = nullptr;
    errno = 0;
    v = std::strtoll(pos_, &end, 10);
    if (end == pos_ || errno == ERANGE || v < lo || v > hi) return false;
    pos_ = end;
    return true;
  }
  bool at_end() const {
    const char* p = pos_;
    while (*p == ' ') ++p;
    return *p == 0;
  }

 private:
  std::istringstream in_;
  std::string where_;
  std::string line_;
  const char* pos_ = "";
  int line_no_ = 0;
};

// A string field, or "" when it is missing or not a string (plan files are checked, never trusted).
std::string str_field(const nlohmann::json& o, const char* key) {
  if (!o.is_object() || !o.contains(key) || !o[key].is_string()) return {};
  return o[key].get<std::string>();
}

// An unsigned field, or 0 when it is missing or not an unsigned number.
std::uint64_t uint_field(const nlohmann::json& o, const char* key) {
  if (!o.is_object() || !o.contains(key) || !o[key].is_number_unsigned()) return 0;
  return o[key].get<std::uint64_t>();
}

// Largest count a plan file may declare (guards the allocations below against a corrupt file).
constexpr long long kMaxCount = 50'000'000;

}  // namespace

std::string garment_to_text(const geometry::Garment& g, bool is_3d) {
  std::string out = std::string(kGarmentFormat) + "\n";
  out += is_3d ? "mode 3d\n" : "mode flat\n";
  out += "vertices " + std::to_string(g.vertices_mm.size()) + "\n";
  for (const auto& v : g.vertices_mm) {
    put(out, v.x), out += ' ', put(out, v.y), out += ' ', put(out, v.z), out += '\n';
  }
  out += "pieces " + std::to_string(g.pieces.size()) + "\n";
  for (const auto& p : g.pieces) {
    const auto& m = p.mesh;
    out += "piece " + std::to_string(p.piece) + " " + std::to_string(m.vertices_mm.size()) + " " +
           std::to_string(m.triangles.size()) + " " + std::to_string(m.edge_vertices.size()) + "\n";
    for (const auto& v : m.vertices_mm) {
      put(out, v.x), out += ' ', put(out, v.y), out += '\n';
    }
    for (const auto& t : m.triangles)
      out += std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    for (const auto& e : m.edge_vertices) {
      out += std::to_string(e.size());
      for (int i : e) out += " " + std::to_string(i);
      out += "\n";
    }
    for (size_t i = 0; i < p.vertex_3d.size(); ++i) out += (i ? " " : "") + std::to_string(p.vertex_3d[i]);
    out += "\n";
  }
  return out;
}

Result<geometry::Garment> garment_from_text(const std::string& text, const std::string& where, bool* is_3d) {
  LineReader r(text, where);
  if (!r.next() || r.line() != kGarmentFormat) return fail(r.error(std::string("not a ") + kGarmentFormat + " file"));
  if (!r.next() || !r.word("mode")) return fail(r.error("expected 'mode 3d' or 'mode flat'"));
  if (r.word("3d")) *is_3d = true;
  else if (r.word("flat")) *is_3d = false;
  else return fail(r.error("expected 'mode 3d' or 'mode flat'"));
  geometry::Garment g;
  long long n = 0;
  if (!r.next() || !r.word("vertices") || !r.integer(n, 0, kMaxCount)) return fail(r.error("expected 'vertices <count>'"));
  g.vertices_mm.resize(static_cast<size_t>(n));
  for (auto& v : g.vertices_mm)
    if (!r.next() || !r.number(v.x) || !r.number(v.y) || !r.number(v.z) || !r.at_end())
      return fail(r.error("expected a vertex 'x y z'"));
  long long pieces = 0;
  if (!r.next() || !r.word("pieces") || !r.integer(pieces, 0, 100000)) return fail(r.error("expected 'pieces <count>'"));
  const long long nv3 = n;
  for (long long k = 0; k < pieces; ++k) {
    geometry::GarmentPiece p;
    long long index = 0, nv = 0, nf = 0, ne = 0;
    if (!r.next() || !r.word("piece") || !r.integer(index, 0, 100000) || !r.integer(nv, 0, kMaxCount) ||
        !r.integer(nf, 0, kMaxCount) || !r.integer(ne, 0, 100000))
      return fail(r.error("expected 'piece <index> <vertices> <triangles> <edges>'"));
    p.piece = static_cast<int>(index);
    p.mesh.vertices_mm.resize(static_cast<size_t>(nv));
    for (auto& v : p.mesh.vertices_mm)
      if (!r.next() || !r.number(v.x) || !r.number(v.y) || !r.at_end()) return fail(r.error("expected a 2D vertex 'x y'"));
    p.mesh.triangles.resize(static_cast<size_t>(nf));
    for (auto& t : p.mesh.triangles) {
      long long a = 0, b = 0, c = 0;
      if (!r.next() || !r.integer(a, 0, nv - 1) || !r.integer(b, 0, nv - 1) || !r.integer(c, 0, nv - 1) || !r.at_end())
        return fail(r.error("expected a triangle of three vertex indices below " + std::to_string(nv)));
      t = {static_cast<int>(a), static_cast<int>(b), static_cast<int>(c)};
    }
    p.mesh.edge_vertices.resize(static_cast<size_t>(ne));
    for (auto& e : p.mesh.edge_vertices) {
      long long count = 0;
      if (!r.next() || !r.integer(count, 0, nv)) return fail(r.error("expected an edge's vertex count"));
      e.resize(static_cast<size_t>(count));
      for (int& i : e) {
        long long x = 0;
        if (!r.integer(x, 0, nv - 1)) return fail(r.error("expected an edge vertex index below " + std::to_string(nv)));
        i = static_cast<int>(x);
      }
      if (!r.at_end()) return fail(r.error("trailing text after the edge's vertices"));
    }
    if (!r.next()) return fail(r.error("expected the piece's 3D vertex indices"));
    p.vertex_3d.resize(static_cast<size_t>(nv));
    for (int& i : p.vertex_3d) {
      long long x = 0;
      if (!r.integer(x, 0, nv3 - 1)) return fail(r.error("expected a 3D vertex index below " + std::to_string(nv3)));
      i = static_cast<int>(x);
    }
    if (!r.at_end()) return fail(r.error("trailing text after the 3D vertex indices"));
    g.pieces.push_back(std::move(p));
  }
  if (r.next() && !r.line().empty()) return fail(r.error("trailing text after the last piece"));
  return g;
}

std::string pieces_to_json(const std::vector<geometry::NestItem>& items) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& it : items) {
    nlohmann::json outline = nlohmann::json::array();
    for (const auto& v : it.outline_mm) outline.push_back({v.x, v.y});
    list.push_back({{"piece", it.piece},
                    {"name", it.name},
                    {"quantity", it.quantity},
                    {"rotation", static_cast<int>(it.rotation)},
                    {"mirror", static_cast<int>(it.mirror)},
                    {"grain", {it.grain.x, it.grain.y}},
                    {"cut_outline_mm", outline}});
  }
  return nlohmann::json{{"format", "tp-pieces-plan/1"}, {"pieces", list}}.dump(1) + "\n";
}

std::string markers_to_json(const std::vector<geometry::Marker>& markers, const geometry::NestStats& stats) {
  nlohmann::json list = nlohmann::json::array();
  for (size_t k = 0; k < markers.size(); ++k) {
    const auto& m = markers[k];
    nlohmann::json pl = nlohmann::json::array();
    for (const auto& p : m.placements)
      pl.push_back({{"piece", p.piece}, {"rotation_deg", p.rotation_deg}, {"mirrored", p.mirrored},
                    {"offset_mm", {p.offset_mm.x, p.offset_mm.y}}});
    nlohmann::json e = {{"width_mm", m.width_mm}, {"length_mm", m.length_mm}, {"utilisation", m.utilisation},
                        {"roll_start_mm", m.roll_start_mm}, {"placements", pl}};
    if (k < stats.iterations.size()) e["search_iterations"] = stats.iterations[k];
    list.push_back(std::move(e));
  }
  return nlohmann::json{{"format", kMarkerFormat}, {"markers", list}}.dump(1) + "\n";
}

Result<std::vector<geometry::Marker>> markers_from_json(const std::string& text, const std::string& where) {
  auto j = nlohmann::json::parse(text, nullptr, false);
  auto bad = [&](const std::string& what) { return fail(ErrorCode::kPipeline, where + ": " + what); };
  if (j.is_discarded() || !j.is_object() || str_field(j, "format") != kMarkerFormat)
    return bad(std::string("not a ") + kMarkerFormat + " file");
  if (!j.contains("markers") || !j["markers"].is_array()) return bad("no markers");
  auto num = [](const nlohmann::json& o, const char* k, double& v) {
    if (!o.is_object() || !o.contains(k) || !o[k].is_number()) return false;
    v = o[k].get<double>();
    return std::isfinite(v);
  };
  std::vector<geometry::Marker> out;
  for (size_t k = 0; k < j["markers"].size(); ++k) {
    const auto& e = j["markers"][k];
    const std::string at = "/markers/" + std::to_string(k);
    geometry::Marker m;
    if (!num(e, "width_mm", m.width_mm) || !num(e, "length_mm", m.length_mm) || !num(e, "utilisation", m.utilisation) ||
        !num(e, "roll_start_mm", m.roll_start_mm) || !e.contains("placements") || !e["placements"].is_array())
      return bad(at + ": width_mm, length_mm, utilisation, roll_start_mm and placements are required");
    for (size_t i = 0; i < e["placements"].size(); ++i) {
      const auto& p = e["placements"][i];
      const std::string pat = at + "/placements/" + std::to_string(i);
      geometry::PiecePlacement pp;
      if (!p.is_object() || !p.contains("piece") || !p["piece"].is_number_integer() || !num(p, "rotation_deg", pp.rotation_deg) ||
          !p.contains("mirrored") || !p["mirrored"].is_boolean() || !p.contains("offset_mm") ||
          !p["offset_mm"].is_array() || p["offset_mm"].size() != 2 || !p["offset_mm"][0].is_number() ||
          !p["offset_mm"][1].is_number())
        return bad(pat + ": piece, rotation_deg, mirrored and offset_mm [x, y] are required");
      pp.piece = p["piece"].get<int>();
      pp.mirrored = p["mirrored"].get<bool>();
      pp.offset_mm = {p["offset_mm"][0].get<double>(), p["offset_mm"][1].get<double>()};
      m.placements.push_back(pp);
    }
    out.push_back(std::move(m));
  }
  return out;
}

PlannedSwath plan_swath(const device::Swath& s) {
  const auto& h = s.header;
  InputHash d;
  d.add("index", static_cast<std::int64_t>(h.index))
      .add("pass", static_cast<std::int64_t>(h.pass))
      .add("direction", static_cast<std::int64_t>(h.direction))
      .add("first_row", h.first_row)
      .add("row_step", static_cast<std::int64_t>(h.row_step))
      .add("rows", static_cast<std::int64_t>(h.rows))
      .add("x_start_px", static_cast<std::int64_t>(h.x_start_px))
      .add("width_px", static_cast<std::int64_t>(h.width_px))
      .add("channels", static_cast<std::int64_t>(h.channels))
      .add("bits_per_pixel", static_cast<std::int64_t>(h.bits_per_pixel))
      .add("feed_before_um", static_cast<std::int64_t>(h.feed_before_um))
      .add("compression", static_cast<std::int64_t>(h.compression))
      .add("raw_bytes", static_cast<std::int64_t>(h.raw_bytes))
      .add("data", std::string_view(reinterpret_cast<const char*>(s.data.data()), s.data.size()));
  return {h.index, h.first_row, h.rows, h.pass, h.feed_before_um, s.data.size(), d.hex()};
}

std::string swaths_to_json(const std::vector<PlannedSwath>& swaths) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : swaths)
    list.push_back({{"index", s.index}, {"first_row", s.first_row}, {"rows", s.rows}, {"pass", s.pass},
                    {"feed_before_um", s.feed_before_um}, {"bytes", s.bytes}, {"digest", s.digest}});
  return nlohmann::json{{"format", kSwathFormat}, {"swaths", list}}.dump(1) + "\n";
}

Result<std::vector<PlannedSwath>> swaths_from_json(const std::string& text, const std::string& where) {
  auto j = nlohmann::json::parse(text, nullptr, false);
  auto bad = [&](const std::string& what) { return fail(ErrorCode::kPipeline, where + ": " + what); };
  if (j.is_discarded() || !j.is_object() || str_field(j, "format") != kSwathFormat || !j.contains("swaths") ||
      !j["swaths"].is_array())
    return bad(std::string("not a ") + kSwathFormat + " file");
  std::vector<PlannedSwath> out;
  for (size_t k = 0; k < j["swaths"].size(); ++k) {
    const auto& e = j["swaths"][k];
    if (!e.is_object() || !e.contains("index") || !e["index"].is_number_unsigned() || !e.contains("digest") ||
        !e["digest"].is_string() || e["index"].get<std::uint64_t>() != k)
      return bad("/swaths/" + std::to_string(k) + ": index " + std::to_string(k) + " and a digest are required");
    PlannedSwath s;
    s.index = static_cast<std::uint32_t>(k);
    s.first_row = static_cast<std::int64_t>(uint_field(e, "first_row"));
    s.rows = static_cast<std::uint32_t>(uint_field(e, "rows"));
    s.pass = static_cast<std::uint16_t>(uint_field(e, "pass"));
    s.feed_before_um = static_cast<std::uint32_t>(uint_field(e, "feed_before_um"));
    s.bytes = uint_field(e, "bytes");
    s.digest = e["digest"].get<std::string>();
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace tp::host::internal
