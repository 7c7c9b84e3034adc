// geometry/cutfile/svg_writer.cpp: marker drawing with one group per cutter layer.
#include "geometry/cutfile/svg_writer.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>

namespace tp::geometry {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v == 0 ? 0.0 : v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string path_data(const std::vector<Vec2>& pts, const Affine2& m, bool closed) {
  std::string d;
  for (size_t i = 0; i < pts.size(); ++i) {
    const Vec2 p = m.apply(pts[i]);
    d += (i == 0 ? "M" : " L") + num(p.x) + "," + num(p.y);
  }
  if (closed && !pts.empty()) d += " Z";
  return d;
}

// An XML id from a piece name: letters, digits, '-', '_' kept, anything else '_'.
std::string id_of(const std::string& name) {
  std::string out;
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return out.empty() ? "piece" : out;
}

// One layer group: a cutter's import selects it by id (Inkscape shows it as a layer).
struct Layer {
  std::string id;
  std::string body;
  void add(const std::string& piece, const std::string& element) {
    body += "  <" + element.substr(0, element.find(' ')) + " data-piece=\"" + escape(piece) + "\"" +
            element.substr(element.find(' ')) + "\n";
  }
};

}  // namespace

std::string svg_text(const CutJob& job) {
  Box2 extent;
  extent.add({0, 0});
  extent.add({job.fabric_width_mm, job.marker_length_mm});
  for (const PieceCut& p : job.pieces)
    for (Vec2 v : p.cut_line) extent.add(p.piece_to_roll.apply(v));
  // The roll, grown to any piece that overhangs it (a marker is not validated here).
  const double x0 = std::min(0.0, extent.min.x), y0 = std::min(0.0, extent.min.y);
  const double w = extent.max.x - x0, h = extent.max.y - y0;
  std::string s;
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" "
       "version=\"1.1\" width=\"" + num(w) + "mm\" height=\"" + num(h) +
       "mm\" viewBox=\"" + num(x0) + " " + num(y0) + " " + num(w) + " " + num(h) + "\">\n";
  s += "<title>" + escape(job.job_name.empty() ? job.pattern_name : job.job_name) +
       " cut contours (mm, roll frame seen from the printed face)</title>\n";
  s += "<style>#cut path{fill:none;stroke:#000;stroke-width:0.3}#sew path{fill:none;stroke:#888;stroke-width:0.2;"
       "stroke-dasharray:2,1}#notch path{fill:none;stroke:#c00;stroke-width:0.3}#grain path{fill:none;stroke:#06c;"
       "stroke-width:0.3}#drill circle{fill:none;stroke:#c0c;stroke-width:0.3}#internal path{fill:none;stroke:#080;"
       "stroke-width:0.2}#annotation path{fill:none;stroke:#999;stroke-width:0.3}#roll rect{fill:none;stroke:#ccc;"
       "stroke-width:0.5}text{font-family:sans-serif;font-size:8px;fill:#333}</style>\n";
  Layer roll{"roll", {}}, cut{"cut", {}}, sew{"sew", {}}, notch{"notch", {}}, drill{"drill", {}}, grain{"grain", {}},
      internal{"internal", {}}, annotation{"annotation", {}};
  roll.body = "  <rect x=\"0\" y=\"0\" width=\"" + num(job.fabric_width_mm) + "\" height=\"" +
              num(job.marker_length_mm) + "\"/>\n";
  for (const PieceCut& p : job.pieces) {
    const Affine2& m = p.piece_to_roll;
    const std::string id = id_of(p.name);
    cut.add(p.name, "path id=\"cut-" + id + "\" d=\"" +
                        path_data(p.cut_line_notched.empty() ? p.cut_line : p.cut_line_notched, m, true) + "\"/>");
    if (!p.sew_line.empty()) sew.add(p.name, "path d=\"" + path_data(p.sew_line, m, true) + "\"/>");
    for (const auto& n : p.notch_shapes) notch.add(p.name, "path d=\"" + path_data(n, m, false) + "\"/>");
    for (const auto& g : p.grain) {
      // A double-headed arrow: the grain runs both ways.
      const Vec2 a = m.apply(g[0]), b = m.apply(g[1]);
      const Vec2 u = normalized(b - a), v = perp(u);
      grain.add(p.name, "path d=\"" + path_data({a, b}, Affine2{}, false) + " " +
                            path_data({b - u * 4 + v * 2, b, b - u * 4 - v * 2}, Affine2{}, false) + " " +
                            path_data({a + u * 4 + v * 2, a, a + u * 4 - v * 2}, Affine2{}, false) + "\"/>");
    }
    for (const auto& l : p.internal_lines) internal.add(p.name, "path d=\"" + path_data(l, m, false) + "\"/>");
    for (const DrillHole& d : p.drill_holes) {
      const Vec2 c = m.apply(d.position_mm);
      drill.add(p.name, "circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" +
                            num(std::max(0.5, 0.5 * d.diameter_mm)) + "\"/>");
    }
    for (const auto& k : p.mark_strokes) annotation.add(p.name, "path d=\"" + path_data(k, m, false) + "\"/>");
    Box2 b;
    for (Vec2 v : p.cut_line) b.add(m.apply(v));
    annotation.add(p.name, "text x=\"" + num(0.5 * (b.min.x + b.max.x)) + "\" y=\"" + num(0.5 * (b.min.y + b.max.y)) +
                               "\" text-anchor=\"middle\">" + escape(p.name) + "</text>");
  }
  for (const Layer* l : {&roll, &cut, &sew, &notch, &drill, &grain, &internal, &annotation})
    s += "<g id=\"" + l->id + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + l->id + "\">\n" + l->body + "</g>\n";
  s += "</svg>\n";
  return s;
}

Status write_svg(const CutJob& job, const std::filesystem::path& path) {
  std::ofstream f(path, std::ios::binary);
  f << svg_text(job);
  f.close();
  if (!f) return fail(ErrorCode::kIo, path.string() + ": cannot write the SVG cut file");
  return {};
}

}  // namespace tp::geometry
