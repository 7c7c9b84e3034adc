// tests/rip/render/marker_source_test.cpp: placing pieces on the roll at print resolution (position,
// rotation, mirror, culling) and the low-resolution marker preview.
#include "rip/render/marker_source.h"

#include <gtest/gtest.h>

#include "host/bench/textured_piece_renderer.h"
#include "rip/render/marker_preview.h"

namespace tp::rip {
namespace {

using geometry::Rgba8;

constexpr Rgba8 kQuadrant[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}};

/// 20x20 texels, one colour per 10x10 quadrant; at 2 texels per mm a 10 mm piece shows each once.
geometry::ImageHandle quadrants() {
  auto img = std::make_shared<geometry::ImageRgba8>();
  img->width_px = 20;
  img->height_px = 20;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) img->pixels.push_back(kQuadrant[(y >= 10) * 2 + (x >= 10)]);
  return img;
}

std::vector<Rgba8> render_all(const MarkerSource& src) {
  std::vector<Rgba8> px(static_cast<size_t>(src.width_px()) * src.height_px());
  for (std::int64_t y = 0; y < src.height_px(); y += kRenderTileRows)
    src.render_rows(y, static_cast<int>(std::min<std::int64_t>(kRenderTileRows, src.height_px() - y)),
                    px.data() + y * src.width_px(), src.width_px());
  return px;
}

TEST(MarkerSource, PiecesLandWhereThePlacementPutsThem) {
  // 254 dpi = 10 px per mm, so mm and pixels line up exactly.
  auto solid = std::make_shared<geometry::ImageRgba8>();
  solid->width_px = solid->height_px = 1;
  solid->pixels = {{10, 20, 30, 255}};
  TexturedPieceRenderer r{{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, solid, 1.0, {}}}};
  geometry::Marker m;
  m.width_mm = 30;
  m.length_mm = 20;
  m.placements = {{0, 0, false, {5, 17}}};  // the face-up flip puts piece y 0..10 at roll y 17..7
  auto src = MarkerSource::create(m, r, 254, 254);
  ASSERT_TRUE(src) << src.error().what();
  EXPECT_EQ((*src)->width_px(), 300);
  EXPECT_EQ((*src)->height_px(), 200);
  const auto px = render_all(**src);
  auto at = [&](int x, int y) { return px[static_cast<size_t>(y) * 300 + x]; };
  EXPECT_EQ(at(50, 70), (Rgba8{10, 20, 30, 255}));
  EXPECT_EQ(at(149, 169), (Rgba8{10, 20, 30, 255}));
  EXPECT_EQ(at(49, 100).a, 0);
  EXPECT_EQ(at(150, 100).a, 0);
  EXPECT_EQ(at(100, 69).a, 0);
  EXPECT_EQ(at(100, 170).a, 0);
  int opaque = 0;
  for (const auto& p : px) opaque += p.a == 255;
  EXPECT_EQ(opaque, 100 * 100);
}

TEST(MarkerSource, RotationAndMirrorFollowPiecePlacement) {
  TexturedPieceRenderer r{{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, quadrants(), 2.0, {}}}};
  for (bool mirrored : {false, true}) {
    geometry::Marker m;
    m.width_mm = 30;
    m.length_mm = 30;
    geometry::PiecePlacement pl{0, 90, mirrored, {15, 5}};
    m.placements = {pl};
    auto src = MarkerSource::create(m, r, 254, 254);
    ASSERT_TRUE(src);
    const auto px = render_all(**src);
    // Every opaque pixel shows the quadrant its centre maps back to in the piece.
    const geometry::Affine2 to_piece = pl.piece_to_roll().inverse();
    int checked = 0;
    for (int y = 0; y < 300; y += 3)
      for (int x = 0; x < 300; x += 3) {
        const geometry::Vec2 q = to_piece.apply({(x + 0.5) / 10, (y + 0.5) / 10});
        if (q.x < 0.5 || q.x > 9.5 || q.y < 0.5 || q.y > 9.5 || std::abs(q.x - 5) < 0.5 || std::abs(q.y - 5) < 0.5)
          continue;  // edges and texel seams blend
        const Rgba8 want = kQuadrant[(q.y >= 5) * 2 + (q.x >= 5)];
        ASSERT_EQ(px[static_cast<size_t>(y) * 300 + x], want) << mirrored << " at " << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 100);
  }
}

TEST(MarkerSource, OnlyPiecesCrossingARowRangeAreVisited) {
  TexturedPieceRenderer r{{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, quadrants(), 1.0, {}}}};
  geometry::Marker m;
  m.width_mm = 50;
  m.length_mm = 100;
  for (int i = 0; i < 5; ++i) m.placements.push_back({0, 0, false, {20, 20.0 * i + 10}});  // y 20i..20i+10
  auto src = MarkerSource::create(m, r, 254, 254);
  ASSERT_TRUE(src);
  EXPECT_EQ((*src)->placements_crossing(0, 16), 1);
  EXPECT_EQ((*src)->placements_crossing(150, 16), 0);   // rows 15..16.6 mm: between pieces
  EXPECT_EQ((*src)->placements_crossing(0, 1000), 5);
}

TEST(MarkerSource, BadPlacementsAreNamed) {
  TexturedPieceRenderer r{{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, quadrants(), 1.0, {}}}};
  geometry::Marker m;
  m.width_mm = 50;
  m.length_mm = 50;
  m.placements = {{0, 0, false, {}}, {3, 0, false, {}}};
  auto a = MarkerSource::create(m, r, 600, 600);
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("marker placement 1 (piece 3)"), std::string::npos) << a.error().message;
  m.placements = {{0, 0, false, {std::nan(""), 0}}};
  EXPECT_FALSE(MarkerSource::create(m, r, 600, 600));
  m.placements.clear();
  m.length_mm = 0;
  EXPECT_FALSE(MarkerSource::create(m, r, 600, 600));
}

TEST(MarkerPreview, RendersTheWholeMarkerSmall) {
  TexturedPieceRenderer r{{{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, quadrants(), 0.02, {}}}};
  geometry::Marker m;
  m.width_mm = 1600;
  m.length_mm = 1000;
  m.placements = {{0, 0, false, {100, 300}}};  // face up: piece y 0..100 at roll y 300..200
  auto img = render_marker_preview(m, r, 50);
  ASSERT_TRUE(img) << img.error().what();
  EXPECT_EQ(img->width_px, 3150);
  EXPECT_EQ(img->height_px, 1969);
  EXPECT_EQ(img->at(0, 0).a, 0);
  EXPECT_EQ(img->at(300, 500).a, 255);  // 152 mm, 254 mm: inside the piece
}

}  // namespace
}  // namespace tp::rip
