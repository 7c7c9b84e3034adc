// geometry/garment/garment_obj.cpp: OBJ writer for garments (3D vertices shared, UVs per piece).
#include "geometry/garment/garment_obj.h"

#include <cstdio>

namespace tp::geometry {
namespace {

// Gap between neighbouring UV islands, mm.
constexpr double kIslandGapMm = 20;

void append(std::string& out, const char* fmt, double a, double b, double c = 0, bool three = false) {
  char buf[96];
  int n = three ? std::snprintf(buf, sizeof buf, fmt, a, b, c) : std::snprintf(buf, sizeof buf, fmt, a, b);
  out.append(buf, static_cast<size_t>(n));
}

}  // namespace

std::string garment_to_obj(const Pattern& pattern, const Garment& g) {
  std::string out;
  out += "# garment " + pattern.name + " size " + pattern.size + "\n";
  out += "# v: 3D positions in mm (y up, z front, x wearer's left); vt: piece coordinates in mm + uv_offset_mm\n";
  for (const Vec3& v : g.vertices_mm) append(out, "v %.4f %.4f %.4f\n", v.x, v.y, v.z, true);
  size_t vt_base = 1;
  double cursor_x = 0;
  for (const GarmentPiece& gp : g.pieces) {
    Box2 b;
    for (Vec2 p : gp.mesh.vertices_mm) b.add(p);
    if (b.empty()) continue;
    const Vec2 off{cursor_x - b.min.x, -b.min.y};
    cursor_x += b.width() + kIslandGapMm;
    const std::string& name = gp.piece >= 0 && gp.piece < static_cast<int>(pattern.pieces.size())
                                  ? pattern.pieces[gp.piece].name
                                  : "piece_" + std::to_string(gp.piece);
    out += "# piece " + name;
    append(out, " uv_offset_mm %.4f %.4f\n", off.x, off.y);
    out += "g " + name + "\n";
    for (Vec2 p : gp.mesh.vertices_mm) append(out, "vt %.4f %.4f\n", p.x + off.x, p.y + off.y);
    for (const auto& t : gp.mesh.triangles) {
      out += "f";
      for (int k = 0; k < 3; ++k)
        out += " " + std::to_string(gp.vertex_3d[t[k]] + 1) + "/" + std::to_string(vt_base + t[k]);
      out += "\n";
    }
    vt_base += gp.mesh.vertices_mm.size();
  }
  return out;
}

}  // namespace tp::geometry
