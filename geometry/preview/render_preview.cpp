// geometry/preview/render_preview.cpp: a small z-buffered triangle rasteriser for garment previews.
#include "geometry/preview/render_preview.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

// Light comes from the viewer's upper left; some ambient keeps back-facing parts readable.
constexpr double kAmbient = 0.35;
const Vec3 kLightDir = normalized(Vec3{-0.35, 0.45, 1.0});
// Piece outlines are drawn this wide in output pixels.
constexpr double kSeamWidthPx = 1.2;
/// Triangles of less area than this (px²) are edge-on to the camera and not drawn.
constexpr double kMinTriangleArea_px2 = 1e-12;

struct Camera {
  PreviewView view;
  // Screen coordinates: right, up, and towards the viewer.
  Vec3 to_view(Vec3 p) const {
    switch (view) {
      case PreviewView::kFront: return {p.x, p.y, p.z};
      case PreviewView::kSide: return {-p.z, p.y, p.x};
      case PreviewView::kBack: return {-p.x, p.y, -p.z};
    }
    return p;
  }
};

struct Canvas {
  int w, h;
  double scale, ox, oy;  // view (mm) -> pixel: x_px = ox + x * scale, y_px = oy - y * scale
  std::vector<float> depth;
  std::vector<Vec3> rgb;

  Vec3 to_px(Vec3 v) const { return {ox + v.x * scale, oy - v.y * scale, v.z}; }

  Vec3 texel(Vec2 uv) const {
    const Vec2 q = tex->piece_mm_to_px.apply(uv);
    const int x = std::clamp(static_cast<int>(std::floor(q.x)), 0, tex->image.width_px - 1);
    const int y = std::clamp(static_cast<int>(std::floor(q.y)), 0, tex->image.height_px - 1);
    const Rgba8 p = tex->image.at(x, y);
    return Vec3{p.r / 255.0, p.g / 255.0, p.b / 255.0};
  }

  // A textured triangle: uv (piece mm) interpolated per pixel (orthographic: affine is exact),
  // the texel found through tex.piece_mm_to_px, times the triangle's shading `light`.
  const PieceTexture* tex = nullptr;
  Vec2 uva, uvb, uvc;
  double light = 1;

  void triangle(Vec3 a, Vec3 b, Vec3 c, Vec3 colour) {
    Vec3 pa = to_px(a), pb = to_px(b), pc = to_px(c);
    double area = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
    if (std::abs(area) < kMinTriangleArea_px2) return;
    int x0 = std::max(0, static_cast<int>(std::floor(std::min({pa.x, pb.x, pc.x}))));
    int x1 = std::min(w - 1, static_cast<int>(std::ceil(std::max({pa.x, pb.x, pc.x}))));
    int y0 = std::max(0, static_cast<int>(std::floor(std::min({pa.y, pb.y, pc.y}))));
    int y1 = std::min(h - 1, static_cast<int>(std::ceil(std::max({pa.y, pb.y, pc.y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        double px = x + 0.5, py = y + 0.5;
        double w0 = ((pb.x - px) * (pc.y - py) - (pb.y - py) * (pc.x - px)) / area;
        double w1 = ((pc.x - px) * (pa.y - py) - (pc.y - py) * (pa.x - px)) / area;
        double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        float z = static_cast<float>(w0 * pa.z + w1 * pb.z + w2 * pc.z);
        size_t i = static_cast<size_t>(y) * w + x;
        if (z <= depth[i]) continue;
        depth[i] = z;
        rgb[i] = tex ? texel(uva * w0 + uvb * w1 + uvc * w2) * light : colour;
      }
  }
};

double light_of(Vec3 a, Vec3 b, Vec3 c) {
  Vec3 n = normalized(cross(b - a, c - a));
  return kAmbient + (1 - kAmbient) * std::abs(dot(n, kLightDir));
}

Vec3 shade(Vec3 base, Vec3 a, Vec3 b, Vec3 c) { return base * light_of(a, b, c); }

}  // namespace

std::string to_string(PreviewView view) {
  switch (view) {
    case PreviewView::kFront: return "front";
    case PreviewView::kSide: return "side";
    case PreviewView::kBack: return "back";
  }
  return "front";
}

Rgba8 piece_colour(int index) {
  // Golden-angle hue steps keep neighbouring indices far apart on the colour wheel.
  double hue = std::fmod(index * 137.508 + 20, 360.0) / 60.0, s = 0.55, v = 0.92;
  double c = v * s, x = c * (1 - std::abs(std::fmod(hue, 2.0) - 1)), m = v - c;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
  }
  const auto u8 = [m](double q) { return static_cast<std::uint8_t>(std::lround((q + m) * 255)); };
  return {u8(r), u8(g), u8(b), 255};
}

ImageRgba8 render_preview(const Garment& garment, const BodyMesh* body, PreviewView view, const PreviewOptions& o) {
  const int ss = std::clamp(o.supersample, 1, 4);
  const Camera cam{view};
  Canvas cv{o.width_px * ss, o.height_px * ss, 1, 0, 0, {}, {}};
  cv.depth.assign(static_cast<size_t>(cv.w) * cv.h, -std::numeric_limits<float>::infinity());
  cv.rgb.assign(static_cast<size_t>(cv.w) * cv.h, Vec3{1, 1, 1});

  // Fit the garment (and body) into the image with a 5 % margin.
  Box2 box;
  for (const Vec3& p : garment.vertices_mm) { Vec3 v = cam.to_view(p); box.add({v.x, v.y}); }
  if (o.draw_body && body)
    for (const Vec3& p : body->vertices_mm) { Vec3 v = cam.to_view(p); box.add({v.x, v.y}); }
  if (box.empty()) box.add({0, 0}), box.add({1, 1});
  cv.scale = 0.9 * std::min(cv.w / std::max(box.width(), kMinDivisor), cv.h / std::max(box.height(), kMinDivisor));
  cv.ox = cv.w / 2.0 - (box.min.x + box.max.x) / 2 * cv.scale;
  cv.oy = cv.h / 2.0 + (box.min.y + box.max.y) / 2 * cv.scale;

  if (o.draw_body && body)
    for (const auto& t : body->triangles) {
      Vec3 a = cam.to_view(body->vertices_mm[t[0]]), b = cam.to_view(body->vertices_mm[t[1]]), c = cam.to_view(body->vertices_mm[t[2]]);
      cv.triangle(a, b, c, shade({0.86, 0.85, 0.83}, a, b, c));
    }
  for (size_t pi = 0; pi < garment.pieces.size(); ++pi) {
    const GarmentPiece& gp = garment.pieces[pi];
    Rgba8 col = piece_colour(static_cast<int>(pi));
    Vec3 base{col.r / 255.0, col.g / 255.0, col.b / 255.0};
    const PieceTexture* tex =
        o.textures && pi < o.textures->size() && !(*o.textures)[pi].image.pixels.empty() ? &(*o.textures)[pi] : nullptr;
    cv.tex = tex;
    for (const auto& t : gp.mesh.triangles) {
      Vec3 a = cam.to_view(garment.vertices_mm[gp.vertex_3d[t[0]]]);
      Vec3 b = cam.to_view(garment.vertices_mm[gp.vertex_3d[t[1]]]);
      Vec3 c = cam.to_view(garment.vertices_mm[gp.vertex_3d[t[2]]]);
      if (tex) {
        cv.uva = gp.mesh.vertices_mm[t[0]], cv.uvb = gp.mesh.vertices_mm[t[1]], cv.uvc = gp.mesh.vertices_mm[t[2]];
        cv.light = light_of(a, b, c);
      }
      cv.triangle(a, b, c, shade(base, a, b, c));
    }
    cv.tex = nullptr;
  }
  // Seams: piece outlines drawn as thin dark quads slightly towards the viewer.
  if (o.draw_seams) {
    const double half = kSeamWidthPx * ss / 2 / cv.scale;
    for (const GarmentPiece& gp : garment.pieces)
      for (const auto& ev : gp.mesh.edge_vertices)
        for (size_t k = 1; k < ev.size(); ++k) {
          Vec3 a = cam.to_view(garment.vertices_mm[gp.vertex_3d[ev[k - 1]]]);
          Vec3 b = cam.to_view(garment.vertices_mm[gp.vertex_3d[ev[k]]]);
          Vec2 d = normalized(Vec2{b.x - a.x, b.y - a.y});
          Vec3 n{-d.y * half, d.x * half, 0}, lift{0, 0, 1.5};
          Vec3 dark{0.15, 0.15, 0.18};
          cv.triangle(a - n + lift, b - n + lift, b + n + lift, dark);
          cv.triangle(a - n + lift, b + n + lift, a + n + lift, dark);
        }
  }

  ImageRgba8 img;
  img.width_px = o.width_px;
  img.height_px = o.height_px;
  img.pixels.resize(static_cast<size_t>(img.width_px) * img.height_px);
  for (int y = 0; y < img.height_px; ++y)
    for (int x = 0; x < img.width_px; ++x) {
      Vec3 sum{};
      for (int sy = 0; sy < ss; ++sy)
        for (int sx = 0; sx < ss; ++sx) sum += cv.rgb[static_cast<size_t>(y * ss + sy) * cv.w + x * ss + sx];
      sum = sum / (ss * ss);
      const auto u8 = [](double q) { return static_cast<std::uint8_t>(std::lround(std::clamp(q, 0.0, 1.0) * 255)); };
      img.at(x, y) = {u8(sum.x), u8(sum.y), u8(sum.z), 255};
    }
  return img;
}

}  // namespace tp::geometry
