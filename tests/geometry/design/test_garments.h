// tests/geometry/design/test_garments.h: garments built by hand for design tests: an N-gore
// flared skirt (planar trapezoid gores on a pyramid frustum, so each chart is exactly isometric
// to its 3D facet) and a flat two-sided panel.
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/common/image.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::test {

struct TestGarment {
  geometry::Pattern pattern;
  geometry::Garment garment;
};

/// Skirt of `gores` trapezoid gores: waist radius `waist_r_mm` (polygon circumradius), hem
/// radius `hem_r_mm`, height `height_mm`, top at y = 0 (hem at y = -height), front at +z.
/// Each gore is meshed on a (cols x rows) grid; gore k's edge "right" is sewn to gore k+1's "left".
inline TestGarment gore_skirt(int gores = 8, double waist_r_mm = 120, double hem_r_mm = 260, double height_mm = 600,
                              int cols = 6, int rows = 30) {
  using namespace geometry;
  TestGarment g;
  g.pattern.name = "gore skirt";
  g.pattern.size = "M";
  const double pi = std::numbers::pi;
  auto ring = [&](double r, double y, int k) {
    const double th = 2 * pi * k / gores - pi / gores;  // gore 0 centred at the front
    return Vec3{r * std::sin(th), y, r * std::cos(th)};
  };
  // 3D vertex ids: column c of gore k (c = 0..cols); column cols of gore k is column 0 of k+1.
  auto vid = [&](int k, int c, int r) {
    const int col = (k * cols + c) % (gores * cols);
    return col * (rows + 1) + r;
  };
  g.garment.vertices_mm.resize(static_cast<size_t>(gores * cols * (rows + 1)));
  for (int k = 0; k < gores; ++k) {
    const Vec3 hl = ring(hem_r_mm, -height_mm, k), hr = ring(hem_r_mm, -height_mm, k + 1);
    const Vec3 wl = ring(waist_r_mm, 0, k), wr = ring(waist_r_mm, 0, k + 1);
    const double a = norm(wr - wl), b = norm(hr - hl);
    const double h = norm((wl + wr) * 0.5 - (hl + hr) * 0.5);
    const Vec2 HL{-b / 2, 0}, HR{b / 2, 0}, WR{a / 2, h}, WL{-a / 2, h};
    Piece pc;
    pc.name = "gore" + std::to_string(k);
    pc.role = "skirt";
    pc.grain = GrainLine{{0, h * 0.2}, {0, h * 0.8}};
    auto edge = [](std::string name, Vec2 p, Vec2 q) {
      Edge e;
      e.name = std::move(name);
      e.points_mm = {p, q};
      return e;
    };
    pc.edges = {edge("hem", HL, HR), edge("right", HR, WR), edge("waist", WR, WL), edge("left", WL, HL)};
    g.pattern.pieces.push_back(pc);

    GarmentPiece gp;
    gp.piece = k;
    auto local = [&](int c, int r) { return r * (cols + 1) + c; };
    for (int r = 0; r <= rows; ++r) {
      for (int c = 0; c <= cols; ++c) {
        const double s = static_cast<double>(c) / cols, t = static_cast<double>(r) / rows;
        gp.mesh.vertices_mm.push_back((HL * (1 - s) + HR * s) * (1 - t) + (WL * (1 - s) + WR * s) * t);
        const Vec3 p3 = (hl * (1 - s) + hr * s) * (1 - t) + (wl * (1 - s) + wr * s) * t;
        gp.vertex_3d.push_back(vid(k, c, r));
        g.garment.vertices_mm[static_cast<size_t>(vid(k, c, r))] = p3;
      }
    }
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        gp.mesh.triangles.push_back({local(c, r), local(c + 1, r), local(c + 1, r + 1)});
        gp.mesh.triangles.push_back({local(c, r), local(c + 1, r + 1), local(c, r + 1)});
      }
    std::vector<int> hem, right, waist, left;
    for (int c = 0; c <= cols; ++c) hem.push_back(local(c, 0));
    for (int r = 0; r <= rows; ++r) right.push_back(local(cols, r));
    for (int c = cols; c >= 0; --c) waist.push_back(local(c, rows));
    for (int r = rows; r >= 0; --r) left.push_back(local(0, r));
    gp.mesh.edge_vertices = {hem, right, waist, left};
    g.garment.pieces.push_back(gp);
  }
  for (int k = 0; k < gores; ++k) {
    Stitch s;
    s.a = {k, 1, 0, -1};
    s.b = {(k + 1) % gores, 3, 0, -1};
    g.pattern.stitches.push_back(s);
  }
  return g;
}

/// A flat rectangular panel (width x height mm) meshed on a grid, placed in the plane z = z_mm
/// facing +z (front) or -z (back), centred on the y axis with its bottom at y = 0.
inline TestGarment flat_panels(double width_mm = 200, double height_mm = 300, bool with_back = false,
                               double gap_mm = 40, int cols = 8, int rows = 12) {
  using namespace geometry;
  TestGarment g;
  g.pattern.name = "panels";
  g.pattern.size = "S";
  for (int side = 0; side < (with_back ? 2 : 1); ++side) {
    Piece pc;
    pc.name = side == 0 ? "front" : "back";
    const Vec2 A{0, 0}, B{width_mm, 0}, C{width_mm, height_mm}, D{0, height_mm};
    auto edge = [](std::string name, Vec2 p, Vec2 q) {
      Edge e;
      e.name = std::move(name);
      e.points_mm = {p, q};
      return e;
    };
    pc.edges = {edge("hem", A, B), edge("right", B, C), edge("top", C, D), edge("left", D, A)};
    pc.grain = GrainLine{{width_mm / 2, 20}, {width_mm / 2, height_mm - 20}};
    g.pattern.pieces.push_back(pc);
    GarmentPiece gp;
    gp.piece = side;
    const int base = static_cast<int>(g.garment.vertices_mm.size());
    auto local = [&](int c, int r) { return r * (cols + 1) + c; };
    for (int r = 0; r <= rows; ++r)
      for (int c = 0; c <= cols; ++c) {
        const Vec2 p{width_mm * c / cols, height_mm * r / rows};
        gp.mesh.vertices_mm.push_back(p);
        // The back panel's chart is seen from behind: x mirrored in 3D.
        const double x3 = side == 0 ? p.x - width_mm / 2 : width_mm / 2 - p.x;
        g.garment.vertices_mm.push_back({x3, p.y, side == 0 ? gap_mm / 2 : -gap_mm / 2});
        gp.vertex_3d.push_back(base + local(c, r));
      }
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        gp.mesh.triangles.push_back({local(c, r), local(c + 1, r), local(c + 1, r + 1)});
        gp.mesh.triangles.push_back({local(c, r), local(c + 1, r + 1), local(c, r + 1)});
      }
    std::vector<int> hem, right, top, left;
    for (int c = 0; c <= cols; ++c) hem.push_back(local(c, 0));
    for (int r = 0; r <= rows; ++r) right.push_back(local(cols, r));
    for (int c = cols; c >= 0; --c) top.push_back(local(c, rows));
    for (int r = rows; r >= 0; --r) left.push_back(local(0, r));
    gp.mesh.edge_vertices = {hem, right, top, left};
    g.garment.pieces.push_back(gp);
  }
  return g;
}

/// An image of `w` x `h` pixels from a function of (x, y).
template <class F>
geometry::ImageHandle make_image(int w, int h, F&& f) {
  auto img = std::make_shared<geometry::ImageRgba8>();
  img->width_px = w;
  img->height_px = h;
  img->pixels.resize(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img->at(x, y) = f(x, y);
  return img;
}

}  // namespace tp::test
