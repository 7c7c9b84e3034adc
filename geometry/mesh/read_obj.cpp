// geometry/mesh/read_obj.cpp: a small OBJ reader, strict about what it keeps, for bodies, garments and textured models.
#include "geometry/mesh/read_obj.h"

#include <charconv>
#include <cmath>
#include <map>

namespace tp::geometry {
namespace {

std::string_view next_word(std::string_view& s) {
  size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
  size_t j = i;
  while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
  std::string_view w = s.substr(i, j - i);
  s.remove_prefix(j);
  return w;
}

bool to_double(std::string_view w, double& out) {
  if (!w.empty() && w.front() == '+') w.remove_prefix(1);
  auto r = std::from_chars(w.data(), w.data() + w.size(), out);
  return r.ec == std::errc() && r.ptr == w.data() + w.size() && std::isfinite(out);
}

bool to_int(std::string_view w, long& out) {
  auto r = std::from_chars(w.data(), w.data() + w.size(), out);
  return r.ec == std::errc() && r.ptr == w.data() + w.size();
}

/// A 1-based or negative (counting back from the latest of `count`) OBJ index to a 0-based one, -1 if out of range.
long resolve_index(long index, size_t count) {
  const long n = static_cast<long>(count);
  const long i = index > 0 ? index - 1 : n + index;
  return i >= 0 && i < n ? i : -1;
}

}  // namespace

Result<ObjMesh> read_obj(std::string_view text, const std::string& file, const ObjReadOptions& options) {
  ObjMesh mesh;
  std::map<std::string, int> group_ids;
  int group = -1;
  int line_no = 0;
  size_t pos = 0;
  std::vector<ObjCorner> corners;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, (nl == std::string_view::npos ? text.size() : nl) - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++line_no;
    auto where = [&] { return file + ":" + std::to_string(line_no) + ": "; };
    std::string_view rest = line;
    std::string_view key = next_word(rest);
    if (key == "v" || key == "vt") {
      double c[3] = {0, 0, 0};
      int need = key == "v" ? 3 : 2;
      for (int k = 0; k < need; ++k) {
        std::string_view w = next_word(rest);
        if (!to_double(w, c[k]))
          return fail(ErrorCode::kParse, where() + std::string(key) + " needs " + std::to_string(need) +
                                             " numbers, found '" + std::string(w.substr(0, 20)) + "'");
      }
      if (key == "v")
        mesh.positions.push_back({c[0], c[1], c[2]});
      else
        mesh.uvs.push_back({c[0], c[1]});
    } else if (key == "g" || key == "o") {
      std::string name(next_word(rest));
      if (name.empty()) name = "default";
      auto [it, inserted] = group_ids.emplace(name, static_cast<int>(mesh.groups.size()));
      if (inserted) mesh.groups.push_back(name);
      group = it->second;
    } else if (key == "f") {
      corners.clear();
      for (std::string_view w = next_word(rest); !w.empty(); w = next_word(rest)) {
        // v, v/vt, v/vt/vn or v//vn: the normal index is not read.
        const size_t s1 = w.find('/');
        const size_t s2 = s1 == std::string_view::npos ? s1 : w.find('/', s1 + 1);
        const std::string_view vs = w.substr(0, s1);
        const std::string_view ts = s1 == std::string_view::npos
                                        ? std::string_view{}
                                        : w.substr(s1 + 1, s2 == std::string_view::npos ? s2 : s2 - s1 - 1);
        if (ts.empty() && options.require_texture_coordinates)
          return fail(ErrorCode::kParse, where() + "face corner '" + std::string(w) + "' has no texture coordinate");
        long vi = 0, ti = 0;
        if (!to_int(vs, vi) || vi == 0 || (!ts.empty() && (!to_int(ts, ti) || ti == 0)))
          return fail(ErrorCode::kParse, where() + "bad face corner '" + std::string(w.substr(0, 40)) + "'");
        const long v = resolve_index(vi, mesh.positions.size());
        if (v < 0)
          return fail(ErrorCode::kParse, where() + "vertex index " + std::to_string(vi) + " out of range (1.." +
                                             std::to_string(mesh.positions.size()) + ")");
        long t = -1;
        if (!ts.empty() && (t = resolve_index(ti, mesh.uvs.size())) < 0)
          return fail(ErrorCode::kParse, where() + "texture index " + std::to_string(ti) + " out of range (1.." +
                                             std::to_string(mesh.uvs.size()) + ")");
        corners.push_back({static_cast<int>(v), static_cast<int>(t)});
      }
      if (corners.size() < 3) return fail(ErrorCode::kParse, where() + "a face needs at least 3 corners");
      for (size_t k = 1; k + 1 < corners.size(); ++k)
        mesh.triangles.push_back(ObjTriangle{{corners[0], corners[k], corners[k + 1]}, group, line_no});
    }
  }
  return mesh;
}

}  // namespace tp::geometry
