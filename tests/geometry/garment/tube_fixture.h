// tests/geometry/garment/tube_fixture.h: a capped cylinder body and a two-panel tube pattern sewn
// round it, shared by the sewing and fit-check tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "geometry/body/body_sdf.h"
#include "geometry/body/marching_tetrahedra.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry::test_fixture {

inline constexpr double kPi = std::numbers::pi;

// A closed capped cylinder of radius r round the vertical line (cx, cz), from y0 to y1.
inline BodySdf cylinder_body(double r, double y0, double y1, double cx = 0) {
  ScalarGrid g;
  g.spacing_mm = 5;
  g.origin_mm = {cx - r - 20, y0 - 20, -r - 20};
  g.nx = g.nz = static_cast<int>(std::ceil((2 * r + 40) / 5)) + 1;
  g.ny = static_cast<int>(std::ceil((y1 - y0 + 40) / 5)) + 1;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        Vec3 p = g.origin_mm + Vec3{double(i), double(j), double(k)} * 5.0;
        g.values.push_back(static_cast<float>(std::max({std::hypot(p.x - cx, p.z) - r, y0 - p.y, p.y - y1})));
      }
  auto sdf = BodySdf::build(marching_tetrahedra(g), 6, 3);
  EXPECT_TRUE(sdf);
  return std::move(*sdf);
}

inline Piece rectangle(const std::string& name, double w, double h) {
  Piece p;
  p.name = name;
  p.role = name;
  p.edges = {Edge{"hem", EdgeCurve::kLine, {}, {{0, 0}, {w, 0}}}, Edge{"right", EdgeCurve::kLine, {}, {{w, 0}, {w, h}}},
             Edge{"top", EdgeCurve::kLine, {}, {{w, h}, {0, h}}}, Edge{"left", EdgeCurve::kLine, {}, {{0, h}, {0, 0}}}};
  return p;
}

// Two flat panels `w` x `h` mm, bottom at height `y`: the front facing +z at `front_z`, the back
// facing -z at `back_z` (negative), their side edges stitched front-right to back-left and back-right
// to front-left.
inline Pattern two_panels(const std::string& name, double w, double h, double y, double front_z, double back_z) {
  Pattern p;
  p.name = name;
  p.pieces = {rectangle("front", w, h), rectangle("back", w, h)};
  p.pieces[0].placement = Placement3d{{1, 0, 0, 0, 1, 0, 0, 0, 1}, {-w / 2, y, front_z}};
  p.pieces[1].placement = Placement3d{{-1, 0, 0, 0, 1, 0, 0, 0, -1}, {w / 2, y, back_z}};
  p.stitches = {Stitch{EdgeSpan{0, 1, 0, -1}, EdgeSpan{1, 3, 0, -1}, false},
                Stitch{EdgeSpan{1, 1, 0, -1}, EdgeSpan{0, 3, 0, -1}, false}};
  return p;
}

// Two panels that close into a tube of radius 115 round a cylinder of radius 100 (y 100..400).
inline Pattern tube_pattern() { return two_panels("tube", kPi * 115, 300, 100, 115, -115); }

}  // namespace tp::geometry::test_fixture
