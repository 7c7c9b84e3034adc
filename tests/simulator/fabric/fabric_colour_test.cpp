// tests/simulator/fabric/fabric_colour_test.cpp: the colorimetric printer gives plausible
// fabric whites, ink hues and tone ramps, fabrics differ, and bad looks are refused.
#include "simulator/fabric/fabric_colour.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace tp::sim {
namespace {

FabricLook cmyk(const std::string& fabric) {
  FabricLook l;
  l.fabric = fabric;
  l.inks = {"cyan", "magenta", "yellow", "black"};
  return l;
}

Lab solid(const FabricColourModel& m, std::size_t ink, std::uint8_t level) {
  std::array<std::uint8_t, 4> p{0, 0, 0, 0};
  p[ink] = level;
  return xyz_to_lab(m.pixel_colour(p));
}

double hue_deg(const Lab& c) {
  const double h = std::atan2(c.b, c.a) * 180.0 / std::numbers::pi;
  return h < 0 ? h + 360 : h;
}

TEST(FabricColour, FabricWhitesAreOffWhiteAndDiffer) {
  for (const char* f : {"cotton", "polyester-satin", "silk"}) {
    auto m = FabricColourModel::create(cmyk(f), 2);
    ASSERT_TRUE(m) << f;
    const Lab w = xyz_to_lab(m->fabric_white());
    EXPECT_GT(w.l, 88) << f;
    EXPECT_LT(w.l, 98) << f;
    EXPECT_GT(w.b, 0) << f << ": unbleached fibre is yellowish";
    EXPECT_LT(w.b, 12) << f;
  }
  auto cotton = FabricColourModel::create(cmyk("cotton"), 2), satin = FabricColourModel::create(cmyk("polyester-satin"), 2);
  EXPECT_GT(delta_e_2000(solid(*cotton, 0, 3), solid(*satin, 0, 3)), 3) << "cyan solid differs by fabric";
  EXPECT_GT(xyz_to_lab(satin->fabric_white()).l, xyz_to_lab(cotton->fabric_white()).l);
}

TEST(FabricColour, SolidsHaveTheirHuesAndRampsDarkenMonotonically) {
  auto m = FabricColourModel::create(cmyk("polyester-satin"), 2);
  ASSERT_TRUE(m);
  const Lab c = solid(*m, 0, 3), mg = solid(*m, 1, 3), y = solid(*m, 2, 3), k = solid(*m, 3, 3);
  EXPECT_GT(hue_deg(c), 180);
  EXPECT_LT(hue_deg(c), 260) << c.a << " " << c.b;
  EXPECT_TRUE(hue_deg(mg) > 320 || hue_deg(mg) < 20) << mg.a << " " << mg.b;
  EXPECT_GT(hue_deg(y), 70);
  EXPECT_LT(hue_deg(y), 110);
  EXPECT_GT(y.l, 80);
  EXPECT_LT(k.l, 25);
  EXPECT_LT(std::hypot(k.a, k.b), 6);
  for (std::size_t ink = 0; ink < 4; ++ink) {
    double last = 101;
    for (std::uint8_t level = 0; level <= 6; ++level) {
      const double l = solid(*m, ink, level).l;
      EXPECT_LT(l, last) << "ink " << ink << " level " << int(level);
      last = l;
    }
  }
}

TEST(FabricColour, AreaColourIsTheMixOfItsPixels) {
  auto m = FabricColourModel::create(cmyk("cotton"), 2);
  ASSERT_TRUE(m);
  // A histogram of one pixel per area equals that pixel.
  std::vector<std::uint32_t> counts(4 * FabricColourModel::kLevelBins, 0);
  for (int k = 0; k < 4; ++k) counts[static_cast<std::size_t>(k * FabricColourModel::kLevelBins)] = 1;
  counts[0] = 0;
  counts[2] = 1;  // cyan level 2
  const std::array<std::uint8_t, 4> px{2, 0, 0, 0};
  const Lab a = xyz_to_lab(m->area_colour(counts, 1)), p = xyz_to_lab(m->pixel_colour(px));
  EXPECT_NEAR(delta_e_2000(a, p), 0, 1e-9);
  // Half the area at level 3 lies between blank and solid.
  counts[2] = 0;
  counts[0] = 1;
  counts[3] = 1;
  for (int k = 1; k < 4; ++k) counts[static_cast<std::size_t>(k * FabricColourModel::kLevelBins)] = 2;
  const Lab half = xyz_to_lab(m->area_colour(counts, 2));
  EXPECT_LT(half.l, xyz_to_lab(m->fabric_white()).l);
  EXPECT_GT(half.l, solid(*m, 0, 3).l);
}

TEST(FabricColour, RefusesUnknownFabricsAndMismatchedLevels) {
  auto bad = cmyk("denim");
  auto m = FabricColourModel::create(bad, 2);
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().message.find("denim"), std::string::npos);
  auto levels = cmyk("silk");
  levels.drop_coverage = {0.5, 1};
  auto n = FabricColourModel::create(levels, 2);
  ASSERT_FALSE(n);
  EXPECT_NE(n.error().message.find("drop_coverage"), std::string::npos);
}

}  // namespace
}  // namespace tp::sim
