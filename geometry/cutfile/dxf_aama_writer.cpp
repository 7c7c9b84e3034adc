// geometry/cutfile/dxf_aama_writer.cpp: DXF R12 group codes for the header, tables, blocks and inserts.
#include "geometry/cutfile/dxf_aama_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <set>

#include "geometry/common/aama_layers.h"

namespace tp::geometry {
namespace {

// ASTM D6673 layer names, from the one table the importer reads too.
constexpr const char* kBoundary = aama_layer_name(AamaLayer::kBoundary);
constexpr const char* kNotch = aama_layer_name(AamaLayer::kNotches);
constexpr const char* kGrain = aama_layer_name(AamaLayer::kGrainLine);
constexpr const char* kInternal = aama_layer_name(AamaLayer::kInternalLines);
constexpr const char* kDrill = aama_layer_name(AamaLayer::kDrillHoles);
constexpr const char* kSew = aama_layer_name(AamaLayer::kSewLines);
constexpr const char* kAnnotation = aama_layer_name(AamaLayer::kAnnotation);
constexpr double kTextHeight_mm = 5;        ///< piece annotation, largest
constexpr double kMinTextHeight_mm = 1;     ///< piece annotation on small pieces
constexpr double kStyleTextHeight_mm = 2.5; ///< file-level Style System Text
constexpr double kStyleTextInset_mm = 3;    ///< from the roll's leading-edge corner
constexpr double kLineSpacing = 1.5;        ///< baseline to baseline, in text heights
constexpr double kCharWidth = 0.7;          ///< a character's advance, in text heights (for fitting)

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
  void text(const char* layer, Vec2 at, const std::string& s, double height_mm) {
    pair(0, "TEXT");
    pair(8, layer);
    point(10, at);
    num(40, height_mm);
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

// Annotation text stacked inside the piece's bounding box, small enough to fit it.
void annotation_texts(Dxf& d, const PieceCut& p) {
  if (p.annotation.empty()) return;
  const Box2 b = bounds(p.sew_line.empty() ? p.cut_line : p.sew_line);
  size_t longest = 1;
  for (const std::string& t : p.annotation) longest = std::max(longest, t.size());
  const double lines = static_cast<double>(p.annotation.size());
  const double height_mm = std::clamp(std::min({kTextHeight_mm, 0.6 * b.height() / (kLineSpacing * lines),
                                                0.8 * b.width() / (kCharWidth * static_cast<double>(longest))}),
                                      kMinTextHeight_mm, kTextHeight_mm);
  Vec2 at{b.min.x + 0.1 * b.width(), 0.5 * (b.min.y + b.max.y) + 0.5 * kLineSpacing * height_mm * (lines - 1)};
  for (const std::string& t : p.annotation) {
    d.text(kBoundary, at, t, height_mm);
    at.y -= kLineSpacing * height_mm;
  }
}

void header(Dxf& d, const CutJob& job, const Affine2& to_cutter) {
  d.pair(999, "cut file: " + (job.job_name.empty() ? job.pattern_name : job.job_name) +
                  " (DXF-AAMA, R12, mm; cutter frame in docs/roll-frame.md)");
  d.pair(0, "SECTION");
  d.pair(2, "HEADER");
  d.pair(9, "$ACADVER");
  d.pair(1, "AC1009");
  // The drawing's extents are the roll's, so an importer zeroing on them keeps the roll's origin.
  Box2 roll;
  roll.add(to_cutter.apply({0, 0}));
  roll.add(to_cutter.apply({job.fabric_width_mm, job.marker_length_mm}));
  d.pair(9, "$EXTMIN");
  d.point(10, roll.min);
  d.pair(9, "$EXTMAX");
  d.point(10, roll.max);
  d.pair(9, "$LIMMIN");
  d.num(10, roll.min.x);
  d.num(20, roll.min.y);
  d.pair(9, "$LIMMAX");
  d.num(10, roll.max.x);
  d.num(20, roll.max.y);
  d.pair(0, "ENDSEC");
}

void tables(Dxf& d) {
  d.pair(0, "SECTION");
  d.pair(2, "TABLES");
  d.pair(0, "TABLE");
  d.pair(2, "LTYPE");
  d.pair(70, "1");
  d.pair(0, "LTYPE");
  d.pair(2, "CONTINUOUS");
  d.pair(70, "0");
  d.pair(3, "Solid line");
  d.pair(72, "65");
  d.pair(73, "0");
  d.num(40, 0);
  d.pair(0, "ENDTAB");
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
  d.pair(0, "TABLE");
  d.pair(2, "STYLE");
  d.pair(70, "1");
  d.pair(0, "STYLE");
  d.pair(2, "STANDARD");
  d.pair(70, "0");
  d.num(40, 0);
  d.num(41, 1);
  d.num(50, 0);
  d.pair(71, "0");
  d.num(42, kTextHeight_mm);
  d.pair(3, "txt");
  d.pair(4, "");
  d.pair(0, "ENDTAB");
  d.pair(0, "ENDSEC");
}

}  // namespace

std::string dxf_aama_text(const CutJob& job) {
  Dxf d;
  const Affine2 to_cutter = roll_to_cutter(job);
  header(d, job, to_cutter);
  tables(d);

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
    // AAMA drill holes are POINTs, whatever the drill's size.
    for (const DrillHole& h : p.drill_holes) {
      d.pair(0, "POINT");
      d.pair(8, kDrill);
      d.point(10, h.position_mm);
    }
    for (const auto& s : p.mark_strokes) d.polyline(kAnnotation, s, false);
    annotation_texts(d, p);
    d.pair(0, "ENDBLK");
    d.pair(8, "0");
  }
  d.pair(0, "ENDSEC");

  d.pair(0, "SECTION");
  d.pair(2, "ENTITIES");
  // Style System Text: the file-level AAMA annotation, in the roll's leading-edge corner.
  std::vector<std::string> style = {"Style Name: " + (job.pattern_name.empty() ? job.job_name : job.pattern_name)};
  if (!job.size.empty()) style.push_back("Sample Size: " + job.size);
  if (!job.job_name.empty()) style.push_back("Job: " + job.job_name);
  style.push_back("Units: METRIC");
  // Text runs along DXF X; lines step away from the corner along DXF Y, staying on the roll.
  const bool x_along = job.roll_axis == CutterRollAxis::kX;
  Vec2 at = to_cutter.apply({kStyleTextInset_mm, kStyleTextInset_mm});
  if (!x_along) at.y -= kStyleTextHeight_mm;
  const Vec2 step{0, (x_along ? 1.0 : -1.0) * kLineSpacing * kStyleTextHeight_mm};
  for (const std::string& t : style) {
    d.text(kBoundary, at, t, kStyleTextHeight_mm);
    at = at + step;
  }
  for (size_t i = 0; i < job.pieces.size(); ++i) {
    const PieceCut& p = job.pieces[i];
    // Block (piece mm) to the cutter's frame: translate * rotate * (x scale -1 if the map
    // mirrors), exactly an INSERT's position, rotation and scale.
    const Affine2 m = to_cutter.compose(p.piece_to_roll);
    const double sx = m.determinant() < 0 ? -1.0 : 1.0;
    const double rot_deg = std::atan2(m.d * sx, m.a * sx) * 180.0 / std::numbers::pi;
    d.pair(0, "INSERT");
    d.pair(8, "0");
    d.pair(2, names[i]);
    d.point(10, {m.c, m.f});
    d.num(41, sx);
    d.num(42, 1);
    d.num(50, rot_deg == 0 ? 0.0 : (rot_deg < 0 ? rot_deg + 360.0 : rot_deg));
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
