// tests/geometry/design/make_piece_renderer_test.cpp: the renderer on hand-made garments: planar
// and cylindrical projection, occlusion, anti-aliased edges, textured allowance, bad input.
#include "geometry/design/make_piece_renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/design/render_piece_image.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

using test::flat_panels;
using test::gore_skirt;
using test::make_image;

Rgba8 quadrant_colour(int x, int y, int w, int h) {
  const bool right = x >= w / 2, bottom = y >= h / 2;
  if (!right && !bottom) return {200, 30, 30, 255};
  if (right && !bottom) return {30, 200, 30, 255};
  if (!right && bottom) return {30, 30, 200, 255};
  return {220, 220, 40, 255};
}

Design planar_quadrants(double z_mm) {
  PlanarProjection p;
  p.image = make_image(64, 96, [](int x, int y) { return quadrant_colour(x, y, 64, 96); });
  p.centre_mm = {0, 150, z_mm};
  p.normal = {0, 0, 1};
  p.up = {0, 1, 0};
  // Wider than the panel, so the image's own transparent border never reaches the piece.
  p.width_mm = 260;
  Design d;
  d.layers.push_back({"quadrants", 1.0, p});
  return d;
}

Finishing no_allowance() {
  Finishing f;
  f.seam_allowance_mm = f.hem_allowance_mm = f.edge_allowance_mm = 0;
  f.marks = MarkMode::kNone;
  return f;
}

// Colour of the pixel whose centre is at piece point p (a 1x1 window).
Rgba8 pixel_at(const PieceRenderer& r, int piece, Vec2 p, double dpi = 300) {
  const double s = 25.4 / dpi;
  Rgba8 px{};
  r.render(piece, Affine2{s, 0, p.x - 0.5 * s, 0, -s, p.y + 0.5 * s}, 1, 1, &px, 1);
  return px;
}

TEST(MakePieceRenderer, PlanarProjectionReproducesTheImageOnAFlatPanel) {
  auto g = flat_panels();
  auto r = make_piece_renderer(g.pattern, g.garment, planar_quadrants(20), no_allowance());
  ASSERT_TRUE(r) << r.error().what();
  // Piece x = 50 is 3D x = -50: the image's left half; piece y = 225 is its upper half.
  EXPECT_EQ(pixel_at(**r, 0, {50, 225}), (Rgba8{200, 30, 30, 255}));
  EXPECT_EQ(pixel_at(**r, 0, {150, 225}), (Rgba8{30, 200, 30, 255}));
  EXPECT_EQ(pixel_at(**r, 0, {50, 75}), (Rgba8{30, 30, 200, 255}));
  EXPECT_EQ(pixel_at(**r, 0, {150, 75}), (Rgba8{220, 220, 40, 255}));
  // Outside the cut outline nothing is written.
  EXPECT_EQ(pixel_at(**r, 0, {-3, 150}).a, 0);
}

TEST(MakePieceRenderer, PlanarProjectionDoesNotPrintThroughToTheBack) {
  auto g = flat_panels(200, 300, /*with_back=*/true);
  auto r = make_piece_renderer(g.pattern, g.garment, planar_quadrants(20), no_allowance());
  ASSERT_TRUE(r) << r.error().what();
  const PieceImage back = render_piece_image(**r, 1, 50);
  int printed = 0;
  for (const Rgba8& p : back.image.pixels) printed += p.a > 0;
  EXPECT_EQ(printed, 0);
  const PieceImage front = render_piece_image(**r, 0, 50);
  int front_printed = 0;
  for (const Rgba8& p : front.image.pixels) front_printed += p.a == 255;
  // 200 x 300 mm at 50 dpi is about 18,600 pixels, all inside the image.
  EXPECT_GT(front_printed, 18000);
}

TEST(MakePieceRenderer, CutOutlineEdgesAreAntiAliasedByCoverage) {
  auto g = flat_panels();
  auto r = make_piece_renderer(g.pattern, g.garment, planar_quadrants(20), no_allowance());
  ASSERT_TRUE(r) << r.error().what();
  // A pixel straddling the left edge (x = 0) by a quarter, half and three quarters; even when
  // its centre is outside, it takes the design colour of its neighbour inside.
  const double s = 25.4 / 100;
  for (double inside : {0.25, 0.5, 0.75}) {
    Rgba8 row[2]{};
    Rgba8& px = row[0];
    (*r)->render(0, Affine2{s, 0, -(1 - inside) * s, 0, -s, 100}, 2, 1, row, 2);
    EXPECT_NEAR(px.a, inside * 255, 1.5) << inside;
    EXPECT_EQ(px.r, 30);  // the colour is the design's, not darkened by coverage
    EXPECT_EQ(row[1].a, 255);
  }
}

TEST(MakePieceRenderer, HemAllowanceMirrorsThePiecesOwnStrip) {
  auto g = flat_panels();
  Finishing f = no_allowance();
  f.edge_allowance_mm = 10;
  auto d = planar_quadrants(20);
  // A horizontal gradient makes the mirror visible.
  std::get<PlanarProjection>(d.layers[0].content).image = make_image(260, 300, [](int x, int) {
    return Rgba8{static_cast<std::uint8_t>(x), 100, 50, 255};
  });
  auto r = make_piece_renderer(g.pattern, g.garment, d, f);
  ASSERT_TRUE(r) << r.error().what();
  for (double depth : {1.0, 4.0, 8.0}) {
    const Rgba8 outside = pixel_at(**r, 0, {-depth, 150});
    const Rgba8 inside = pixel_at(**r, 0, {depth, 150});
    EXPECT_EQ(outside.a, 255);
    EXPECT_NEAR(outside.r, inside.r, 1) << depth;
  }
}

TEST(MakePieceRenderer, CylindricalProjectionIsContinuousAcrossEverySeam) {
  auto g = gore_skirt();
  CylindricalProjection c;
  // A smooth two-period ramp around and a ramp along: any seam mismatch shows as a jump.
  c.image = make_image(256, 128, [](int x, int y) {
    const double a = 2 * std::numbers::pi * x / 256.0;
    return Rgba8{static_cast<std::uint8_t>(128 + 100 * std::sin(2 * a)), static_cast<std::uint8_t>(2 * y),
                 static_cast<std::uint8_t>(128 + 100 * std::cos(a)), 255};
  });
  Design d;
  d.layers.push_back({"ramp", 1.0, c});
  auto r = make_piece_renderer(g.pattern, g.garment, d, no_allowance());
  ASSERT_TRUE(r) << r.error().what();
  for (int k = 0; k < 8; ++k) {
    const auto& right = g.pattern.pieces[static_cast<size_t>(k)].edges[1].points_mm;
    const auto& left = g.pattern.pieces[static_cast<size_t>((k + 1) % 8)].edges[3].points_mm;
    for (double t : {0.1, 0.5, 0.9}) {
      // Right edge runs up from the hem; the partner's left edge runs down from the waist.
      const Vec2 a = right[0] + (right[1] - right[0]) * t;
      const Vec2 b = left[0] + (left[1] - left[0]) * (1 - t);
      // Half a pixel inside each piece: both sides of the same 3D seam point.
      const Rgba8 pa = pixel_at(**r, k, a + Vec2{-0.05, 0});
      const Rgba8 pb = pixel_at(**r, (k + 1) % 8, b + Vec2{0.05, 0});
      EXPECT_NEAR(pa.r, pb.r, 3) << "seam " << k << " t " << t;
      EXPECT_NEAR(pa.g, pb.g, 3);
      EXPECT_NEAR(pa.b, pb.b, 3);
    }
  }
}

// A kept base reuses the occlusion map and image pyramid of an earlier design (same plane, same
// image object, another size): the renderer is still the one a fresh build makes, pixel for pixel.
TEST(MakePieceRenderer, AKeptBaseRendersTheSameAsAFreshBuildAfterOtherDesigns) {
  auto g = flat_panels(200, 300, /*with_back=*/true);
  RenderOptions keep;
  keep.keep_layer_data = true;
  auto base = prepare_piece_renderer(g.pattern, g.garment, no_allowance(), keep);
  ASSERT_TRUE(base) << base.error().what();
  Design a = planar_quadrants(20);
  auto first = make_piece_renderer(*base, a);
  ASSERT_TRUE(first) << first.error().what();
  Design b = a;
  std::get<PlanarProjection>(b.layers[0].content).width_mm = 140;
  auto kept = make_piece_renderer(*base, b);
  auto fresh = make_piece_renderer(g.pattern, g.garment, b, no_allowance());
  ASSERT_TRUE(kept && fresh);
  for (int piece = 0; piece < (*fresh)->piece_count(); ++piece) {
    const PieceImage x = render_piece_image(**kept, piece, 40), y = render_piece_image(**fresh, piece, 40);
    ASSERT_EQ(x.image.pixels.size(), y.image.pixels.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < x.image.pixels.size(); ++i) differ += !(x.image.pixels[i] == y.image.pixels[i]);
    EXPECT_EQ(differ, 0u) << "piece " << piece;
  }
  // And the first design's renderer is untouched by the second.
  EXPECT_EQ(pixel_at(**first, 0, {50, 225}), (Rgba8{200, 30, 30, 255}));
}

TEST(MakePieceRenderer, RejectsAGarmentThatDoesNotMatchThePattern) {
  auto g = gore_skirt();
  g.garment.pieces[3].vertex_3d[5] = 999999;
  auto r = make_piece_renderer(g.pattern, g.garment, Design{}, Finishing{});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("piece 'gore3'"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("vertex_3d[5]"), std::string::npos) << r.error().message;
}

TEST(MakePieceRenderer, RejectsAnInvalidDesignNamingTheLayerAndField) {
  auto g = gore_skirt();
  Design d;
  BrushStroke b;
  b.points_mm = {{0, -100, 200}};
  b.radius_mm = -1;
  d.layers.push_back({"flower", 1.0, b});
  auto r = make_piece_renderer(g.pattern, g.garment, d, Finishing{});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("design.layers[0] 'flower'"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("radius_mm"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace tp::geometry
