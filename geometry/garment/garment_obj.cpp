// geometry/garment/garment_obj.cpp: OBJ and MTL writers for garments (3D vertices shared, UVs per piece).
#include "geometry/garment/garment_obj.h"

#include <algorithm>
#include <cstdio>

namespace tp::geometry {
namespace {

// Gap between neighbouring UV islands when no atlas is given, mm.
constexpr double kIslandGapMm = 20;

void append(std::string& out, const char* fmt, double a, double b, double c = 0, bool three = false) {
  char buf[96];
  int n = three ? std::snprintf(buf, sizeof buf, fmt, a, b, c) : std::snprintf(buf, sizeof buf, fmt, a, b);
  out.append(buf, static_cast<size_t>(n));
}

}  // namespace

std::string garment_to_obj(const Pattern& pattern, const Garment& g, const GarmentTexture* texture) {
  std::string out;
  out += "# garment " + pattern.name + " size " + pattern.size + "\n";
  out += "# units: mm (1 OBJ unit = 1 mm; scale by 0.001 where a tool reads units as metres)\n";
  if (texture) {
    out += "# v: 3D positions in mm (y up, z front, x wearer's left); vt: place in " + texture->texture_file +
           " normalised to [0,1], v up\n";
    out += "mtllib " + texture->mtl_file + "\n";
  } else {
    out += "# v: 3D positions in mm (y up, z front, x wearer's left); vt: piece coordinates in mm + uv_offset_mm\n";
  }
  for (const Vec3& v : g.vertices_mm) append(out, "v %.4f %.4f %.4f\n", v.x, v.y, v.z, true);
  if (texture) out += "usemtl " + texture->material + "\n";
  size_t vt_base = 1;
  double cursor_x = 0;
  for (const GarmentPiece& gp : g.pieces) {
    Box2 b;
    for (Vec2 p : gp.mesh.vertices_mm) b.add(p);
    if (b.empty()) continue;
    const bool known = gp.piece >= 0 && gp.piece < static_cast<int>(pattern.pieces.size());
    const std::string name = known ? pattern.pieces[static_cast<size_t>(gp.piece)].name : "piece_" + std::to_string(gp.piece);
    out += "g " + name + "\n";
    if (texture && known && static_cast<size_t>(gp.piece) < texture->piece_mm_to_atlas_px.size()) {
      // Atlas pixel (row 0 on top) -> OBJ texture space (v up), clamped against rounding at the edges.
      const Affine2& to_px = texture->piece_mm_to_atlas_px[static_cast<size_t>(gp.piece)];
      const double w = std::max(1, texture->width_px), h = std::max(1, texture->height_px);
      for (Vec2 p : gp.mesh.vertices_mm) {
        const Vec2 px = to_px.apply(p);
        append(out, "vt %.6f %.6f\n", std::clamp(px.x / w, 0.0, 1.0), std::clamp(1.0 - px.y / h, 0.0, 1.0));
      }
    } else {
      const Vec2 off{cursor_x - b.min.x, -b.min.y};
      cursor_x += b.width() + kIslandGapMm;
      out += "# piece " + name;
      append(out, " uv_offset_mm %.4f %.4f\n", off.x, off.y);
      for (Vec2 p : gp.mesh.vertices_mm) append(out, "vt %.4f %.4f\n", p.x + off.x, p.y + off.y);
    }
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

std::string garment_mtl(const GarmentTexture& texture) {
  return "# printed pieces of the garment, packed into " + texture.texture_file + "\n"
         "newmtl " + texture.material + "\n"
         "Ka 1.000 1.000 1.000\n"
         "Kd 1.000 1.000 1.000\n"
         "Ks 0.000 0.000 0.000\n"
         "d 1.0\n"
         "illum 1\n"
         "map_Kd " + texture.texture_file + "\n";
}

}  // namespace tp::geometry
