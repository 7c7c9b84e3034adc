// tests/rip/colour/soft_proof_test.cpp: a soft proof through a press profile keeps greys, clips
// saturated sRGB green and marks it in the overlay.
#include "rip/colour/soft_proof.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "rip/colour/ink_converter.h"

namespace tp::rip {
namespace {

TEST(SoftProof, GreysStayCloseAndSaturatedGreenIsOutOfGamut) {
  if (!std::filesystem::exists(kDefaultCmykProfilePath)) GTEST_SKIP() << "no " << kDefaultCmykProfilePath;
  geometry::ImageRgba8 design;
  design.width_px = 3;
  design.height_px = 1;
  design.pixels = {{128, 128, 128, 255}, {0, 255, 0, 255}, {255, 255, 255, 255}};
  geometry::ImageRgba8 proof, overlay;
  auto s = soft_proof(design, kDefaultCmykProfilePath, proof, &overlay);
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->printed_pixels, 2u);
  EXPECT_GE(s->out_of_gamut_share, 0.5) << "the green at least";
  EXPECT_GT(s->worst_de00, 5);
  EXPECT_NEAR(proof.pixels[0].g, 128, 6);
  EXPECT_LT(proof.pixels[1].g, 250) << "press green is duller";
  EXPECT_EQ(overlay.pixels[1].g, 255);
  EXPECT_EQ(overlay.pixels[1].r, 0);
  EXPECT_EQ(proof.pixels[2].r, 255) << "unprinted stays";
}

// Colours are tallied once each (a marker holds tens of megapixels, far fewer colours); two
// colours that share a slot of that tally (the same green, blue and low four bits of red) must
// each keep their own figure.
TEST(SoftProof, ColoursSharingATallySlotKeepTheirOwnDifference) {
  if (!std::filesystem::exists(kDefaultCmykProfilePath)) GTEST_SKIP() << "no " << kDefaultCmykProfilePath;
  const geometry::Rgba8 blue{0, 0, 255, 255}, violet{240, 0, 255, 255};
  auto alone = [](geometry::Rgba8 c) {
    geometry::ImageRgba8 design, proof;
    design.width_px = 1;
    design.height_px = 1;
    design.pixels = {c};
    auto s = soft_proof(design, kDefaultCmykProfilePath, proof, nullptr);
    EXPECT_TRUE(s);
    return s ? s->worst_de00 : 0.0;
  };
  const double de_blue = alone(blue), de_violet = alone(violet);
  ASSERT_GT(std::abs(de_blue - de_violet), 0.5) << "the test needs two different figures";
  for (const auto& order : {std::vector{blue, violet, blue, violet}, std::vector{violet, blue, violet, blue}}) {
    geometry::ImageRgba8 design, proof;
    design.width_px = 4;
    design.height_px = 1;
    design.pixels = order;
    auto s = soft_proof(design, kDefaultCmykProfilePath, proof, nullptr);
    ASSERT_TRUE(s) << s.error().message;
    EXPECT_EQ(s->printed_pixels, 4u);
    EXPECT_DOUBLE_EQ(s->worst_de00, std::max(de_blue, de_violet));
  }
}

TEST(SoftProof, NamesAProfileItCannotRead) {
  geometry::ImageRgba8 design, proof;
  auto s = soft_proof(design, "/nonexistent/p.icc", proof, nullptr);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("/nonexistent/p.icc"), std::string::npos);
}

}  // namespace
}  // namespace tp::rip
