// geometry/body/load_body_obj.cpp: a small, strict OBJ reader for body meshes.
#include "geometry/body/load_body_obj.h"

#include <charconv>
#include <fstream>
#include <sstream>
#include <vector>

namespace tp::geometry {
namespace {

std::string_view next_token(std::string_view& s) {
  size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) { s = {}; return {}; }
  size_t e = s.find_first_of(" \t\r", b);
  std::string_view tok = s.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b);
  s = e == std::string_view::npos ? std::string_view{} : s.substr(e);
  return tok;
}

bool parse_double(std::string_view t, double& v) {
  auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ec == std::errc() && p == t.data() + t.size() && std::isfinite(v);
}

}  // namespace

Result<BodyMesh> parse_body_obj(std::string_view text, double mm_per_unit, const std::string& source) {
  if (!(mm_per_unit > 0)) return fail(ErrorCode::kInvalidArgument, source + ": units scale must be > 0");
  BodyMesh mesh;
  mesh.name = source;
  int line_no = 0;
  while (!text.empty()) {
    size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    ++line_no;
    const auto where = [&] { return source + ":" + std::to_string(line_no); };
    std::string_view rest = line;
    std::string_view kind = next_token(rest);
    if (kind == "v") {
      double c[3];
      for (double& x : c)
        if (!parse_double(next_token(rest), x)) return fail(ErrorCode::kParse, where() + ": vertex needs three numbers");
      mesh.vertices_mm.push_back(Vec3{c[0], c[1], c[2]} * mm_per_unit);
    } else if (kind == "f") {
      std::vector<int> idx;
      for (std::string_view tok = next_token(rest); !tok.empty(); tok = next_token(rest)) {
        std::string_view vi = tok.substr(0, tok.find('/'));
        long v = 0;
        auto [p, ec] = std::from_chars(vi.data(), vi.data() + vi.size(), v);
        if (ec != std::errc() || p != vi.data() + vi.size() || v == 0)
          return fail(ErrorCode::kParse, where() + ": bad face index '" + std::string(tok) + "'");
        long n = static_cast<long>(mesh.vertices_mm.size());
        long i = v > 0 ? v - 1 : n + v;
        if (i < 0 || i >= n)
          return fail(ErrorCode::kParse, where() + ": face index " + std::to_string(v) + " out of range (" + std::to_string(n) + " vertices)");
        idx.push_back(static_cast<int>(i));
      }
      if (idx.size() < 3) return fail(ErrorCode::kParse, where() + ": face needs at least 3 vertices");
      for (size_t k = 1; k + 1 < idx.size(); ++k) mesh.triangles.push_back({idx[0], idx[k], idx[k + 1]});
    }
  }
  if (mesh.triangles.empty()) return fail(ErrorCode::kParse, source + ": no faces");
  return mesh;
}

Result<BodyMesh> load_body_obj(const std::string& path, double mm_per_unit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, path + ": cannot open");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_body_obj(ss.str(), mm_per_unit, path);
}

}  // namespace tp::geometry
