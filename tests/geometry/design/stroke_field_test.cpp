// tests/geometry/design/stroke_field_test.cpp: brush strokes on the garment surface: a stroke
// across a seam lands on both pieces, distances never cut through the body, edges are soft.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/render_piece_image.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

Rgba8 pixel_at(const PieceRenderer& r, int piece, Vec2 p, double dpi = 300) {
  const double s = 25.4 / dpi;
  Rgba8 px{};
  r.render(piece, Affine2{s, 0, p.x - 0.5 * s, 0, -s, p.y + 0.5 * s}, 1, 1, &px, 1);
  return px;
}

Finishing plain() {
  Finishing f;
  f.marks = MarkMode::kNone;
  return f;
}

TEST(BrushStroke, AStrokeAcrossASeamLandsOnBothPieces) {
  auto g = test::gore_skirt();
  // A horizontal stroke round the front at mid height, from gore 7 across gore 0 to gore 1.
  BrushStroke b;
  for (int k = -30; k <= 30; ++k) {
    const double a = k * std::numbers::pi / 180;
    b.points_mm.push_back({400 * std::sin(a), -300, 400 * std::cos(a)});
  }
  b.radius_mm = 8;
  b.hardness = 1;
  b.colour = {200, 20, 20, 255};
  Design d;
  d.layers.push_back({"stroke", 1.0, b});
  auto r = make_piece_renderer(g.pattern, g.garment, d, plain());
  ASSERT_TRUE(r) << r.error().what();
  // The stroke snaps onto the flared skirt a little below height -300; gore charts have the hem
  // at y = 0, so it crosses the seams somewhere around chart y = 250..300. Scan for it.
  auto seam_x = [&](int piece, bool right, double y) {
    const auto& e = g.pattern.pieces[static_cast<size_t>(piece)].edges[right ? 1 : 3].points_mm;
    const double t = (y - e[0].y) / (e[1].y - e[0].y);
    return e[0].x + (e[1].x - e[0].x) * t;
  };
  int hits0 = 0, hits1 = 0, both = 0;
  for (double y = 150; y <= 450; y += 0.5) {
    const bool a = pixel_at(**r, 0, {seam_x(0, true, y) - 0.5, y}).a == 255;
    const bool c = pixel_at(**r, 1, {seam_x(1, false, y) + 0.5, y}).a == 255;
    hits0 += a;
    hits1 += c;
    both += a && c;
  }
  // About 16 mm of stroke height on each side of the seam (at 0.5 mm steps), at the same heights.
  EXPECT_GT(hits0, 25);
  EXPECT_LT(hits0, 40);
  EXPECT_NEAR(hits0, hits1, 2);
  EXPECT_GE(both, hits0 - 2);
  // Far from the stroke, and on the back of the skirt, nothing.
  EXPECT_EQ(pixel_at(**r, 0, {0, 100}).a, 0);
  EXPECT_EQ(pixel_at(**r, 4, {0, 300}).a, 0);
}

TEST(BrushStroke, DistancesAreMeasuredOnTheSurfaceNotThroughTheBody) {
  // Front and back panels 20 mm apart, not sewn together: a 30 mm brush on the front is within
  // 30 mm of the back panel in space but far from it on the garment.
  auto g = test::flat_panels(200, 300, /*with_back=*/true, /*gap_mm=*/20);
  BrushStroke b;
  b.points_mm = {{-50, 150, 10}, {50, 150, 10}};
  b.radius_mm = 30;
  b.hardness = 0.5;
  b.colour = {0, 0, 0, 255};
  Design d;
  d.layers.push_back({"stroke", 1.0, b});
  auto r = make_piece_renderer(g.pattern, g.garment, d, plain());
  ASSERT_TRUE(r) << r.error().what();
  const PieceImage back = render_piece_image(**r, 1, 50);
  int printed = 0;
  for (const Rgba8& p : back.image.pixels) printed += p.a > 0;
  EXPECT_EQ(printed, 0);
  // The front gets it, full in the core and soft towards the radius.
  EXPECT_EQ(pixel_at(**r, 0, {100, 150}).a, 255);
  const int mid = pixel_at(**r, 0, {100, 150 + 24}).a;
  EXPECT_GT(mid, 10);
  EXPECT_LT(mid, 245);
  EXPECT_EQ(pixel_at(**r, 0, {100, 150 + 32}).a, 0);
}

TEST(TextureTransfer, ResamplesAModelPaintedInAnotherTool) {
  auto g = test::flat_panels(200, 300);
  // The painted model: a quad over the front panel, 1 mm in front of it, its UVs the unit square.
  TextureTransfer t;
  t.vertices_mm = {{-100, 0, 21}, {100, 0, 21}, {100, 300, 21}, {-100, 300, 21}};
  t.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  t.triangles = {{0, 1, 2}, {0, 2, 3}};
  t.uv_triangles = t.triangles;
  t.image = test::make_image(64, 96, [](int x, int y) {
    return x < 32 ? (y < 48 ? Rgba8{250, 0, 0, 255} : Rgba8{0, 250, 0, 255}) : Rgba8{0, 0, 250, 255};
  });
  Design d;
  d.layers.push_back({"painted", 1.0, t});
  auto r = make_piece_renderer(g.pattern, g.garment, d, plain());
  ASSERT_TRUE(r) << r.error().what();
  EXPECT_EQ(pixel_at(**r, 0, {50, 225}), (Rgba8{250, 0, 0, 255}));  // UV (0.25, 0.75): image top left
  EXPECT_EQ(pixel_at(**r, 0, {50, 75}), (Rgba8{0, 250, 0, 255}));
  EXPECT_EQ(pixel_at(**r, 0, {150, 150}), (Rgba8{0, 0, 250, 255}));
  // A model farther than max_distance_mm from the garment leaves it unprinted.
  for (Vec3& v : t.vertices_mm) v.z += 100;
  d.layers[0].content = t;
  auto far = make_piece_renderer(g.pattern, g.garment, d, plain());
  ASSERT_TRUE(far);
  EXPECT_EQ(pixel_at(**far, 0, {50, 225}).a, 0);
}

TEST(DesignLayers, CompositeBottomFirstWithOpacity) {
  auto g = test::flat_panels(200, 300);
  PlanarProjection base;
  base.image = test::make_image(4, 4, [](int, int) { return Rgba8{0, 0, 200, 255}; });
  base.centre_mm = {0, 150, 20};
  base.width_mm = 400;
  PlanarProjection top = base;
  top.image = test::make_image(4, 4, [](int, int) { return Rgba8{200, 0, 0, 255}; });
  Design d;
  d.layers.push_back({"base", 1.0, base});
  d.layers.push_back({"top", 0.5, top});
  auto r = make_piece_renderer(g.pattern, g.garment, d, plain());
  ASSERT_TRUE(r) << r.error().what();
  const Rgba8 p = pixel_at(**r, 0, {100, 150});
  EXPECT_NEAR(p.r, 100, 2);
  EXPECT_NEAR(p.b, 100, 2);
  EXPECT_EQ(p.a, 255);
}

}  // namespace
}  // namespace tp::geometry
