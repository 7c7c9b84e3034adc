// tests/geometry/design/make_overlay_renderer_test.cpp: an overlay renderer (text and labels)
// that keeps only the region it prints renders what the full renderer of the same design does.
#include <gtest/gtest.h>

#include <cstdlib>

#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/render_piece_image.h"
#include "tests/geometry/design/test_garments.h"

namespace tp::geometry {
namespace {

// A front "number" on a gore skirt: a planar image that does not repeat.
Design number_layer() {
  Design d;
  PlanarProjection p;
  p.image = test::make_image(40, 20, [](int x, int y) {
    return (x / 5 + y / 5) % 2 ? Rgba8{250, 250, 250, 255} : Rgba8{20, 30, 90, 128};
  });
  p.centre_mm = {0, -250, 300};
  p.normal = {0, 0, 1};
  p.up = {0, 1, 0};
  p.width_mm = 160;
  d.layers.push_back({"number", 1.0, p});
  return d;
}

TEST(MakeOverlayRenderer, KeepsOnlyWhatPrintsAndRendersAsTheFullRenderer) {
  const auto g = test::gore_skirt();
  Finishing f;
  f.job_name = "kit 3/12";
  f.marks = MarkMode::kPrinted;
  auto base = prepare_piece_renderer(g.pattern, g.garment, f);
  ASSERT_TRUE(base);
  auto full = make_piece_renderer(*base, number_layer());
  auto overlay = make_overlay_renderer(*base, number_layer());
  ASSERT_TRUE(full && overlay);
  // The full renderer keeps the base alive; the overlay (no stroke layer) does not.
  full->reset();
  EXPECT_EQ(base->use_count(), 1);
  auto full_again = make_piece_renderer(*base, number_layer());
  ASSERT_TRUE(full_again);
  long printed = 0;
  for (double dpi : {50.0, 150.0}) {
    for (int piece = 0; piece < (*overlay)->piece_count(); ++piece) {
      EXPECT_EQ((*overlay)->cut_outline_mm(piece), (*full_again)->cut_outline_mm(piece));
      const PieceImage want = render_piece_image(**full_again, piece, dpi);
      const PieceImage got = render_piece_image(**overlay, piece, dpi);
      ASSERT_EQ(want.image.pixels.size(), got.image.pixels.size());
      long off = 0;
      for (size_t i = 0; i < want.image.pixels.size(); ++i) {
        const Rgba8 a = want.image.pixels[i], b = got.image.pixels[i];
        const int d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
        off += d > 2;
        printed += a.a > 0;
      }
      EXPECT_EQ(off, 0) << "piece " << piece << " at " << dpi << " dpi: " << off << " pixels differ";
    }
  }
  EXPECT_GT(printed, 1000);  // the number and the labels do print
}

TEST(MakeOverlayRenderer, RefusesANonPositiveMargin) {
  const auto g = test::gore_skirt();
  auto base = prepare_piece_renderer(g.pattern, g.garment, Finishing{});
  ASSERT_TRUE(base);
  auto r = make_overlay_renderer(*base, number_layer(), 0);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("margin_mm"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
