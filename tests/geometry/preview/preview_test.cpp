// tests/geometry/preview/preview_test.cpp: the software rasteriser's views and colours.
#include <gtest/gtest.h>

#include <set>

#include "geometry/preview/render_preview.h"

namespace tp::geometry {
namespace {

// One 200 x 100 mm piece standing in the z = 0 plane, facing the front, on the wearer's left.
Garment panel() {
  Garment g;
  GarmentPiece gp;
  gp.mesh.vertices_mm = {{0, 0}, {200, 0}, {200, 100}, {0, 100}};
  gp.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  gp.mesh.edge_vertices = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  gp.vertex_3d = {0, 1, 2, 3};
  g.pieces = {gp};
  for (Vec2 v : gp.mesh.vertices_mm) g.vertices_mm.push_back({v.x + 100, v.y, 0});
  return g;
}

bool white(Rgba8 c) { return c.r == 255 && c.g == 255 && c.b == 255; }

TEST(RenderPreview, FrontAndBackSeeThePieceSideSeesAnEdge) {
  Garment g = panel();
  PreviewOptions o{.width_px = 200, .height_px = 100, .supersample = 1, .draw_body = false, .draw_seams = false};
  ImageRgba8 front = render_preview(g, nullptr, PreviewView::kFront, o);
  ASSERT_EQ(front.width_px, 200);
  ASSERT_EQ(front.pixels.size(), 200u * 100u);
  // Fitted with a 5 % margin: the centre is the piece, the corners are background.
  EXPECT_FALSE(white(front.at(100, 50)));
  EXPECT_TRUE(white(front.at(2, 2)));
  Rgba8 c = piece_colour(0);
  // Facing the light: shading keeps the hue order of the piece colour.
  EXPECT_EQ(front.at(100, 50).r > front.at(100, 50).b, c.r > c.b);
  ImageRgba8 back = render_preview(g, nullptr, PreviewView::kBack, o);
  EXPECT_FALSE(white(back.at(100, 50)));
  ImageRgba8 side = render_preview(g, nullptr, PreviewView::kSide, o);
  int coloured = 0;
  for (Rgba8 p : side.pixels) coloured += !white(p);
  EXPECT_LT(coloured, 200);  // edge-on: at most a line of pixels
}

TEST(RenderPreview, NearerPieceHidesFartherOne) {
  Garment g = panel();
  // A second piece 50 mm in front of the first, covering its left half.
  GarmentPiece gp = g.pieces[0];
  for (int& v : gp.vertex_3d) v += 4;
  for (int i = 0; i < 4; ++i) g.vertices_mm.push_back(g.vertices_mm[i] + Vec3{-100, 0, 50});
  g.pieces.push_back(gp);
  PreviewOptions o{.width_px = 300, .height_px = 100, .supersample = 1, .draw_body = false, .draw_seams = false};
  ImageRgba8 front = render_preview(g, nullptr, PreviewView::kFront, o);
  ImageRgba8 back = render_preview(g, nullptr, PreviewView::kBack, o);
  // Overlap (x 100..200 mm) is the middle of the image: piece 1 in front, piece 0 from the back.
  Rgba8 f = front.at(150, 50), b = back.at(150, 50);
  EXPECT_NE(f, b);
}

TEST(PieceColour, DistinctForNeighbouringPieces) {
  std::set<std::tuple<int, int, int>> seen;
  for (int i = 0; i < 10; ++i) {
    Rgba8 c = piece_colour(i);
    EXPECT_EQ(c.a, 255);
    seen.insert({c.r / 8, c.g / 8, c.b / 8});
  }
  EXPECT_EQ(seen.size(), 10u);
}

TEST(RenderPreview, TexturedPieceShowsItsPrintWhereItsUvsPutIt) {
  // A texture of the panel at 1 px/mm: red on its left half (piece x < 100), blue on its right.
  Garment g = panel();
  std::vector<PieceTexture> tex(1);
  tex[0].image.width_px = 200, tex[0].image.height_px = 100;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 200; ++x)
      tex[0].image.pixels.push_back(x < 100 ? Rgba8{230, 20, 20, 255} : Rgba8{20, 20, 230, 255});
  tex[0].piece_mm_to_px = Affine2{};  // identity: pixel (x, y) is piece mm (x, y)
  PreviewOptions o{.width_px = 200, .height_px = 100, .supersample = 1, .draw_body = false, .draw_seams = false};
  o.textures = &tex;
  // From the front the piece's x runs to the image's right: red left of centre, blue right.
  ImageRgba8 front = render_preview(g, nullptr, PreviewView::kFront, o);
  const Rgba8 l = front.at(60, 50), r = front.at(140, 50);
  EXPECT_GT(l.r, 3 * l.b) << int(l.r) << "," << int(l.b);
  EXPECT_GT(r.b, 3 * r.r) << int(r.r) << "," << int(r.b);
  // From the back the halves swap sides.
  ImageRgba8 back = render_preview(g, nullptr, PreviewView::kBack, o);
  EXPECT_GT(back.at(60, 50).b, 3 * back.at(60, 50).r);
  EXPECT_GT(back.at(140, 50).r, 3 * back.at(140, 50).b);
}

}  // namespace
}  // namespace tp::geometry
