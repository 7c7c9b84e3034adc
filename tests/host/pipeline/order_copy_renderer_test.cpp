// tests/host/pipeline/order_copy_renderer_test.cpp: a copy's text drawn over its size's shared
// renderer prints what one renderer of every layer prints, labels included.
#include "host/pipeline/order_copy_renderer.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/render_piece_image.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::host {
namespace {

using namespace geometry;

// A gore skirt with a cylindrical stripe under a half-transparent front planar "text" layer.
Design layers(bool stripe, bool text) {
  Design d;
  if (stripe) {
    CylindricalProjection c;
    c.image = test::make_image(64, 64, [](int x, int) {
      return x < 32 ? Rgba8{200, 40, 40, 255} : Rgba8{40, 40, 200, 255};
    });
    c.axis_origin_mm = Vec3{0, 0, 0};
    c.tile_width_mm = 150;
    c.tile_height_mm = 150;
    d.layers.push_back({"stripe", 1.0, c});
  }
  if (text) {
    PlanarProjection p;
    p.image = test::make_image(40, 20, [](int x, int y) {
      return (x / 5 + y / 5) % 2 ? Rgba8{250, 250, 250, 255} : Rgba8{20, 30, 90, 128};
    });
    p.centre_mm = {0, -250, 300};
    p.normal = {0, 0, 1};
    p.up = {0, 1, 0};
    p.width_mm = 160;
    d.layers.push_back({"number", 1.0, p});
  }
  return d;
}

TEST(OrderCopyRenderer, SharedBasePlusCopyOverlayPrintsAsOneRendererOfAllLayers) {
  const auto g = test::gore_skirt();
  Finishing f;
  f.job_name = "kit 3/12";
  Finishing unlabelled = f;
  unlabelled.marks = MarkMode::kNone;
  auto full = make_piece_renderer(g.pattern, g.garment, layers(true, true), f);
  auto base = make_piece_renderer(g.pattern, g.garment, layers(true, false), unlabelled);
  auto overlay = make_piece_renderer(g.pattern, g.garment, layers(false, true), f);
  ASSERT_TRUE(full && base && overlay);
  const OrderCopyRenderer copy(std::shared_ptr<const PieceRenderer>(std::move(*base)),
                               std::shared_ptr<const PieceRenderer>(std::move(*overlay)));
  ASSERT_EQ(copy.piece_count(), (*full)->piece_count());
  long text_pixels = 0;
  for (int piece = 0; piece < copy.piece_count(); ++piece) {
    EXPECT_EQ(copy.cut_outline_mm(piece), (*full)->cut_outline_mm(piece));
    const PieceImage want = render_piece_image(**full, piece, 50);
    const PieceImage got = render_piece_image(copy, piece, 50, 2, 16);
    ASSERT_EQ(want.image.width_px, got.image.width_px);
    ASSERT_EQ(want.image.height_px, got.image.height_px);
    long inside = 0, off = 0;
    for (size_t i = 0; i < want.image.pixels.size(); ++i) {
      const Rgba8 a = want.image.pixels[i], b = got.image.pixels[i];
      if (a.a != 255) continue;  // the outline's anti-aliased edge: the text's alpha applies twice there
      ++inside;
      const int d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
      off += d > 2;
      text_pixels += std::abs(a.r - 250) < 3 && std::abs(a.g - 250) < 3;
    }
    EXPECT_GT(inside, 1000) << piece;
    EXPECT_EQ(off, 0) << "piece " << piece << ": " << off << " of " << inside << " pixels differ";
  }
  EXPECT_GT(text_pixels, 100);  // the overlay's layer does print on the front gores
}

}  // namespace
}  // namespace tp::host
