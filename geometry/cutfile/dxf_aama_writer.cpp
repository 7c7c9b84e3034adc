// geometry/cutfile/dxf_aama_writer.cpp: DXF R12 group codes for blocks, entities and inserts.
#include "geometry/cutfile/dxf_aama_writer.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

namespace tp::geometry {
namespace {

// ASTM D6673 layer numbers.
constexpr const char* kBoundary = "1";
constexpr const char* kNotch = "4";
constexpr const char* kGrain = "7";
constexpr const char* kInternal = "8";
constexpr const char* kDrill = "13";
constexpr const char* kSew = "14";
constexpr const char* kAnnotation = "15";
constexpr double kTextHeight_mm = 5;

class Dxf {
 public:
  void pair(int code, const std::string& value) {
    out_ += std::to_string(code);
    out_ += '\n';
    out_ += value;
    out_ += '\n';
  }
  void num(int code, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", v == 0 ? 0.0 : v);  // no "-0.0000"
    pair(code, buf);
  }
  void point(int code, Vec2 p) {
    num(code, p.x);
    num(code + 10, p.y);
    num(code + 20, 0);
  }
  void polyline(const char* layer, const std::vector<Vec2>& pts, bool closed) {
    if (pts.size() < 2) return;
    pair(0, "POLYLINE");
    pair(8, layer);
    pair(66, "1");
    point(10, {0, 0});
    pair(70, closed ? "1" : "0");
    for (Vec2 p : pts) {
      pair(0, "VERTEX");
      pair(8, layer);
      point(10, p);
    }
    pair(0, "SEQEND");
    pair(8, layer);
  }
  void line(const char* layer, Vec2 a, Vec2 b) {
    pair(0, "LINE");
    pair(8, layer);
    point(10, a);
    point(11, b);
  }
  void text(const char* layer, Vec2 at, const std::string& s) {
    pair(0, "TEXT");
    pair(8, layer);
    point(10, at);
    num(40, kTextHeight_mm);
    pair(1, s);
  }
  std::string out_;
};

std::string block_name(const std::string& name, std::set<std::string>& used) {
  std::string s;
  for (char c : name) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') ? c : '_';
  if (s.empty() || s[0] == '*') s = "piece" + s;
  std::string unique = s;
  for (int k = 2; used.count(unique); ++k) unique = s + "_" + std::to_string(k);
  used.insert(unique);
  return unique;
}

}  // namespace

std::string dxf_aama_text(const CutJob& job) {
  Dxf d;
  d.pair(999, "cut file: " + (job.job_name.empty() ? job.pattern_name : job.job_name) + " (DXF-AAMA, mm)");
  d.pair(0, "SECTION");
  d.pair(2, "HEADER");
  d.pair(9, "$ACADVER");
  d.pair(1, "AC1009");
  d.pair(9, "$INSUNITS");
  d.pair(70, "4");
  d.pair(9, "$MEASUREMENT");
  d.pair(70, "1");
  d.pair(0, "ENDSEC");

  d.pair(0, "SECTION");
  d.pair(2, "TABLES");
  d.pair(0, "TABLE");
  d.pair(2, "LAYER");
  const char* layers[] = {"0", kBoundary, kNotch, kGrain, kInternal, kDrill, kSew, kAnnotation};
  d.pair(70, std::to_string(std::size(layers)));
  for (const char* l : layers) {
    d.pair(0, "LAYER");
    d.pair(2, l);
    d.pair(70, "0");
    d.pair(62, "7");
    d.pair(6, "CONTINUOUS");
  }
  d.pair(0, "ENDTAB");
  d.pair(0, "ENDSEC");

  std::set<std::string> used;
  std::vector<std::string> names;
  d.pair(0, "SECTION");
  d.pair(2, "BLOCKS");
  for (const PieceCut& p : job.pieces) {
    const std::string name = block_name(p.name, used);
    names.push_back(name);
    d.pair(0, "BLOCK");
    d.pair(8, "0");
    d.pair(2, name);
    d.pair(70, "0");
    d.point(10, {0, 0});
    d.pair(3, name);
    d.polyline(kBoundary, p.cut_line_notched.empty() ? p.cut_line : p.cut_line_notched, true);
    d.polyline(kSew, p.sew_line, true);
    for (const auto& n : p.notch_lines) d.line(kNotch, n[0], n[1]);
    for (const auto& g : p.grain) d.line(kGrain, g[0], g[1]);
    for (const auto& l : p.internal_lines) d.polyline(kInternal, l, false);
    for (const DrillHole& h : p.drill_holes) {
      if (h.diameter_mm > 0) {
        d.pair(0, "CIRCLE");
        d.pair(8, kDrill);
        d.point(10, h.position_mm);
        d.num(40, 0.5 * h.diameter_mm);
      } else {
        d.pair(0, "POINT");
        d.pair(8, kDrill);
        d.point(10, h.position_mm);
      }
    }
    for (const auto& s : p.mark_strokes) d.polyline(kAnnotation, s, false);
    // Annotation text stacked inside the piece, below its grain line's start (or its centre).
    const Box2 b = bounds(p.sew_line.empty() ? p.cut_line : p.sew_line);
    Vec2 at = p.grain.empty() ? Vec2{b.min.x + 0.25 * b.width(), b.min.y + 0.5 * b.height()} : p.grain.front()[0];
    for (const std::string& t : p.annotation) {
      d.text(kBoundary, at, t);
      at.y -= 1.5 * kTextHeight_mm;
    }
    d.pair(0, "ENDBLK");
    d.pair(8, "0");
  }
  d.pair(0, "ENDSEC");

  d.pair(0, "SECTION");
  d.pair(2, "ENTITIES");
  for (size_t i = 0; i < job.pieces.size(); ++i) {
    const PieceCut& p = job.pieces[i];
    // piece_to_roll = translate * rotate * mirror: exactly an INSERT's scale, rotation, position.
    const Affine2& m = p.piece_to_roll;
    const double sx = p.mirrored ? -1.0 : 1.0;
    const double rot_deg = std::atan2(m.d * sx, m.a * sx) * 180.0 / 3.14159265358979323846;
    d.pair(0, "INSERT");
    d.pair(8, "0");
    d.pair(2, names[i]);
    d.point(10, {m.c, m.f});
    d.num(41, sx);
    d.num(42, 1);
    d.num(50, rot_deg);
  }
  d.pair(0, "ENDSEC");
  d.pair(0, "EOF");
  return std::move(d.out_);
}

Status write_dxf_aama(const CutJob& job, const std::filesystem::path& path) {
  std::ofstream f(path, std::ios::binary);
  const std::string text = dxf_aama_text(job);
  f << text;
  f.close();
  if (!f) return fail(ErrorCode::kIo, path.string() + ": cannot write the DXF cut file");
  return {};
}

}  // namespace tp::geometry
