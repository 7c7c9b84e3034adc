// tests/host/bench/textured_piece_renderer_test.cpp: the benchmark's stand-in renderer covers each piece's
// area within an edge budget and composites over what is already there.
#include "host/bench/textured_piece_renderer.h"

#include <cmath>

#include <gtest/gtest.h>

namespace tp::rip {
namespace {

geometry::ImageHandle solid(geometry::Rgba8 c) {
  auto img = std::make_shared<geometry::ImageRgba8>();
  img->width_px = img->height_px = 1;
  img->pixels = {c};
  return img;
}

/// Sum of alpha over a window, in pixels of full coverage.
double coverage(const TexturedPieceRenderer& r, const geometry::Affine2& m, int w, int h) {
  std::vector<geometry::Rgba8> px(static_cast<size_t>(w) * h);
  r.render(0, m, w, h, px.data(), w);
  double sum = 0;
  for (const auto& p : px) sum += p.a / 255.0;
  return sum;
}

TEST(TexturedPieceRenderer, CoverageMatchesAreaWithinTheEdgeBudget) {
  // A rotated rectangle and a triangle, 0.1 mm pixels; the budget is 0.1 px per pixel of outline.
  const geometry::Polygon rect{{0, 0}, {20, 0}, {20, 7}, {0, 7}};
  const geometry::Polygon tri{{0, 0}, {15, 2}, {4, 11}};
  for (const auto& poly : {rect, tri}) {
    TexturedPieceRenderer r{{{poly, solid({1, 2, 3, 255}), 1.0, {}}}};
    for (double deg : {0.0, 17.0, 45.0, 90.0}) {
      // pixel -> piece: scale 0.1 mm, centre, rotate about the piece's middle: it fits the window.
      geometry::Vec2 mid;
      for (auto v : poly) mid += v / static_cast<double>(poly.size());
      const geometry::Affine2 m = geometry::Affine2::translation(mid)
                                      .compose(geometry::Affine2::rotation_deg(deg))
                                      .compose(geometry::Affine2::translation({-15, -15}))
                                      .compose(geometry::Affine2::scale(0.1, 0.1));
      double perimeter_px = 0;
      for (size_t i = 0; i < poly.size(); ++i) perimeter_px += geometry::norm(poly[(i + 1) % poly.size()] - poly[i]) * 10;
      const double area_px = std::abs(geometry::signed_area(poly)) * 100;
      EXPECT_NEAR(coverage(r, m, 300, 300), area_px, 0.1 * perimeter_px) << deg;
    }
  }
}

TEST(TexturedPieceRenderer, CompositesOverExistingPixelsAndLeavesOthers) {
  TexturedPieceRenderer r{{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, solid({200, 0, 0, 128}), 1.0, {}}}};
  std::vector<geometry::Rgba8> px(4, {0, 0, 200, 255});
  // 2 x 2 pixels of 1 mm; the piece covers pixel (0, 0) only.
  r.render(0, geometry::Affine2::scale(1, 1), 2, 2, px.data(), 2);
  EXPECT_EQ(px[0].a, 255);
  EXPECT_NEAR(px[0].r, 100, 1);
  EXPECT_NEAR(px[0].b, 100, 1);
  EXPECT_EQ(px[1], (geometry::Rgba8{0, 0, 200, 255}));
  EXPECT_EQ(px[3], (geometry::Rgba8{0, 0, 200, 255}));
}

}  // namespace
}  // namespace tp::rip
