// geometry/cutfile/svg_writer.cpp: marker drawing with one group per piece.
#include "geometry/cutfile/svg_writer.h"

#include <algorithm>
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
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(w) + "mm\" height=\"" + num(h) +
       "mm\" viewBox=\"" + num(x0) + " " + num(y0) + " " + num(w) + " " + num(h) + "\">\n";
  s += "<title>" + escape(job.job_name.empty() ? job.pattern_name : job.job_name) + " cut contours (mm)</title>\n";
  s += "<style>.cut{fill:none;stroke:#000;stroke-width:0.3}.sew{fill:none;stroke:#888;stroke-width:0.2;"
       "stroke-dasharray:2,1}.notch{fill:none;stroke:#c00;stroke-width:0.3}.grain{stroke:#06c;stroke-width:0.3}"
       ".drill{fill:none;stroke:#c0c;stroke-width:0.3}.internal{fill:none;stroke:#080;stroke-width:0.2}"
       ".mark{fill:none;stroke:#999;stroke-width:0.3}.roll{fill:none;stroke:#ccc;stroke-width:0.5}"
       "text{font-family:sans-serif;font-size:8px;fill:#333}</style>\n";
  s += "<rect class=\"roll\" x=\"0\" y=\"0\" width=\"" + num(job.fabric_width_mm) + "\" height=\"" + num(job.marker_length_mm) + "\"/>\n";
  for (const PieceCut& p : job.pieces) {
    const Affine2& m = p.piece_to_roll;
    s += "<g id=\"" + escape(p.name) + "\">\n";
    s += "<path class=\"cut\" d=\"" + path_data(p.cut_line_notched.empty() ? p.cut_line : p.cut_line_notched, m, true) + "\"/>\n";
    if (!p.sew_line.empty()) s += "<path class=\"sew\" d=\"" + path_data(p.sew_line, m, true) + "\"/>\n";
    for (const auto& n : p.notch_shapes) s += "<path class=\"notch\" d=\"" + path_data(n, m, false) + "\"/>\n";
    for (const auto& g : p.grain) {
      // A double-headed arrow: the grain runs both ways.
      const Vec2 a = m.apply(g[0]), b = m.apply(g[1]);
      const Vec2 u = normalized(b - a), v = perp(u);
      s += "<path class=\"grain\" d=\"" + path_data({a, b}, Affine2{}, false) + " " +
           path_data({b - u * 4 + v * 2, b, b - u * 4 - v * 2}, Affine2{}, false) + " " +
           path_data({a + u * 4 + v * 2, a, a + u * 4 - v * 2}, Affine2{}, false) + "\"/>\n";
    }
    for (const auto& l : p.internal_lines) s += "<path class=\"internal\" d=\"" + path_data(l, m, false) + "\"/>\n";
    for (const DrillHole& d : p.drill_holes) {
      const Vec2 c = m.apply(d.position_mm);
      s += "<circle class=\"drill\" cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(std::max(0.5, 0.5 * d.diameter_mm)) + "\"/>\n";
    }
    for (const auto& k : p.mark_strokes) s += "<path class=\"mark\" d=\"" + path_data(k, m, false) + "\"/>\n";
    Box2 b;
    for (Vec2 v : p.cut_line) b.add(m.apply(v));
    s += "<text x=\"" + num(0.5 * (b.min.x + b.max.x)) + "\" y=\"" + num(0.5 * (b.min.y + b.max.y)) +
         "\" text-anchor=\"middle\">" + escape(p.name) + "</text>\n";
    s += "</g>\n";
  }
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
