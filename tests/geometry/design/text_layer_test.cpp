// tests/geometry/design/text_layer_test.cpp: text shaped and rendered for personalised layers.
#include "geometry/design/text_layer.h"

#include <gtest/gtest.h>

#include <fstream>

namespace tp::geometry {
namespace {

// Rows and columns holding ink (alpha above half).
struct InkBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  long pixels = 0;
};
InkBox ink_box(const ImageRgba8& img) {
  InkBox b;
  for (int y = 0; y < img.height_px; ++y)
    for (int x = 0; x < img.width_px; ++x)
      if (img.at(x, y).a > 127) {
        b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
        b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
        ++b.pixels;
      }
  return b;
}

TEST(TextLayer, CapitalsComeOutTheAskedHeight) {
  TextStyle s;
  s.cap_height_mm = 30;
  s.px_per_mm = 10;
  auto t = render_text_image("HH", s);
  ASSERT_TRUE(t) << t.error().message;
  EXPECT_EQ(t->glyphs, 2);
  const InkBox b = ink_box(t->image);
  ASSERT_GT(b.pixels, 0);
  // An H is flat at top and bottom: its inked rows are the cap height (within a pixel each end).
  EXPECT_NEAR(b.y1 - b.y0 + 1, 300, 2);
  EXPECT_NEAR(t->width_mm, t->image.width_px / 10.0, 1e-9);
  EXPECT_GT(t->width_mm, 30);  // two capitals are wider than one is tall
}

TEST(TextLayer, TheImageIsCroppedToTheInkAndItsOffsetKeepsTheBaseline) {
  TextStyle s;
  s.cap_height_mm = 30;
  s.px_per_mm = 10;
  auto caps = render_text_image("H", s);
  auto descender = render_text_image("Hy", s);
  ASSERT_TRUE(caps && descender);
  // Only a border of at most 2 transparent texels is left around the ink.
  for (const TextImage* t : {&*caps, &*descender}) {
    InkBox any;
    for (int y = 0; y < t->image.height_px; ++y)
      for (int x = 0; x < t->image.width_px; ++x)
        if (t->image.at(x, y).a > 0) {
          any.x0 = std::min(any.x0, x), any.x1 = std::max(any.x1, x);
          any.y0 = std::min(any.y0, y), any.y1 = std::max(any.y1, y);
        }
    EXPECT_LE(any.x0, 2);
    EXPECT_LE(any.y0, 2);
    EXPECT_GE(any.x1, t->image.width_px - 3);
    EXPECT_GE(any.y1, t->image.height_px - 3);
  }
  // The H's foot (the baseline) lies at the same height above the line's centre in both: the
  // image of "Hy" reaches lower, and its offset says by how much.
  auto foot_up_mm = [](const TextImage& t) {
    int foot = -1;
    for (int y = 0; y < t.image.height_px; ++y)
      for (int x = 0; x < t.image.width_px / 4; ++x)
        if (t.image.at(x, y).a > 127) foot = y;
    return t.offset_up_mm + t.height_mm / 2 - (foot + 1) / 10.0;
  };
  EXPECT_GT(caps->height_mm, 30);
  EXPECT_GT(descender->height_mm, caps->height_mm + 5);
  EXPECT_NEAR(foot_up_mm(*caps), foot_up_mm(*descender), 0.1);
}

TEST(TextLayer, GlyphsAreInkedInTheColourAndTheSameEveryTime) {
  TextStyle s;
  s.cap_height_mm = 20;
  s.colour = {200, 10, 20, 255};
  auto a = render_text_image("ANNA 7", s);
  auto b = render_text_image("ANNA 7", s);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->image.pixels, b->image.pixels);
  EXPECT_EQ(a->glyphs, 6);
  long solid = 0;
  for (const Rgba8& p : a->image.pixels)
    if (p.a == 255) {
      ++solid;
      EXPECT_EQ(p, (Rgba8{200, 10, 20, 255}));
    }
  EXPECT_GT(solid, 1000);
  auto other = render_text_image("ANNA 8", s);
  ASSERT_TRUE(other);
  EXPECT_NE(other->image.pixels, a->image.pixels);
}

TEST(TextLayer, AnOutlineRingsTheLettersInItsColour) {
  TextStyle s;
  s.cap_height_mm = 20;
  s.colour = {0, 0, 0, 255};
  auto plain = render_text_image("O", s);
  s.outline_mm = 1.5;
  s.outline_colour = {255, 255, 0, 255};
  auto ringed = render_text_image("O", s);
  ASSERT_TRUE(plain && ringed);
  long yellow = 0;
  for (const Rgba8& p : ringed->image.pixels) yellow += p == Rgba8{255, 255, 0, 255};
  EXPECT_GT(yellow, 500);
  EXPECT_GT(ink_box(ringed->image).pixels, ink_box(plain->image).pixels);
  // The ring adds about 1.5 mm each side.
  EXPECT_NEAR(
      (ink_box(ringed->image).x1 - ink_box(ringed->image).x0) - (ink_box(plain->image).x1 - ink_box(plain->image).x0),
      30, 4);
}

TEST(TextLayer, BadInputIsNamed) {
  TextStyle s;
  EXPECT_FALSE(render_text_image("", s));
  s.font_file = "/nonexistent/font.ttf";
  auto r = render_text_image("A", s);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("/nonexistent/font.ttf"), std::string::npos);
  const auto junk = std::filesystem::temp_directory_path() / "tp-text-layer-junk.ttf";
  std::ofstream(junk) << "not a font";
  s.font_file = junk;
  r = render_text_image("A", s);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("not a font"), std::string::npos);
  std::filesystem::remove(junk);
}

}  // namespace
}  // namespace tp::geometry
