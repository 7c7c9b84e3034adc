// tests/geometry/design/textures_test.cpp: procedural textures: tileable, deterministic, shaped.
#include "geometry/design/textures.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace tp::geometry {
namespace {

int diff(Rgba8 a, Rgba8 b) { return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b); }

TEST(Textures, MarblingTilesSeamlesslyAndRepeatsForASeed) {
  MarblingOptions o;
  o.width_px = o.height_px = 256;
  const ImageRgba8 a = marbling(o), b = marbling(o);
  EXPECT_EQ(a.pixels, b.pixels);
  o.seed = 2;
  EXPECT_NE(marbling(o).pixels, a.pixels);
  // Across the tile's wrap (last column to first) the colour changes no more than between any
  // two neighbouring columns inside it.
  long wrap = 0, inside = 0;
  for (int y = 0; y < 256; ++y) {
    wrap += diff(a.at(255, y), a.at(0, y)) + diff(a.at(y, 255), a.at(y, 0));
    inside += diff(a.at(127, y), a.at(128, y)) + diff(a.at(y, 127), a.at(y, 128));
  }
  EXPECT_LT(wrap, 2 * inside + 256);
}

TEST(Textures, StripesCycleThroughTheColours) {
  const ImageRgba8 s = stripes(100, 10, 4, true, {{255, 0, 0, 255}, {0, 0, 255, 255}});
  EXPECT_EQ(s.at(10, 5), (Rgba8{255, 0, 0, 255}));
  EXPECT_EQ(s.at(35, 5), (Rgba8{0, 0, 255, 255}));
  EXPECT_EQ(s.at(60, 5), (Rgba8{255, 0, 0, 255}));
  const ImageRgba8 h = stripes(10, 100, 2, false, {{0, 0, 0, 255}, {255, 255, 255, 255}});
  EXPECT_EQ(h.at(5, 10).r, 0);
  EXPECT_EQ(h.at(5, 90).r, 255);
}

TEST(Textures, MotifIsOpaqueInTheMiddleAndClearInTheCorners) {
  const ImageRgba8 m = placement_motif(128);
  EXPECT_EQ(m.at(64, 64).a, 255);
  EXPECT_EQ(m.at(1, 1).a, 0);
  EXPECT_EQ(m.at(126, 126).a, 0);
}

}  // namespace
}  // namespace tp::geometry
