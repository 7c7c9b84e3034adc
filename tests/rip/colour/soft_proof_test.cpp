// tests/rip/colour/soft_proof_test.cpp: a soft proof through a press profile keeps greys, clips
// saturated sRGB green and marks it in the overlay.
#include "rip/colour/soft_proof.h"

#include <gtest/gtest.h>

#include <filesystem>

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

TEST(SoftProof, NamesAProfileItCannotRead) {
  geometry::ImageRgba8 design, proof;
  auto s = soft_proof(design, "/nonexistent/p.icc", proof, nullptr);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("/nonexistent/p.icc"), std::string::npos);
}

}  // namespace
}  // namespace tp::rip
