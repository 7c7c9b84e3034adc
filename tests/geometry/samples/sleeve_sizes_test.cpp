// tests/geometry/samples/sleeve_sizes_test.cpp: the sleeved samples' sleeves keep size M's cap
// proportions in every size (a narrow, tall cap in S crumpled and tangled on sewing).
#include <gtest/gtest.h>

#include <string>

#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"

namespace tp::geometry {
namespace {

struct SleeveShape {
  double bicep_mm = 0, cap_height_mm = 0, cap_mm = 0;
};

SleeveShape sleeve_shape(const std::string& garment, const std::string& size) {
  auto m = samples::standard_size(size);
  EXPECT_TRUE(m);
  auto p = samples::draft_garment(garment, *m, size);
  EXPECT_TRUE(p) << p.error().what();
  for (const Piece& pc : p->pieces) {
    if (pc.name != "sleeve_l") continue;
    const Box2 bb = bounds(outline(pc));
    for (const Edge& e : pc.edges)
      if (e.name == "cap") return {bb.width(), bb.max.y, edge_length_mm(e)};
  }
  ADD_FAILURE() << garment << " " << size << ": no sleeve_l with a cap";
  return {};
}

class SleeveSizes : public ::testing::TestWithParam<std::string> {};

TEST_P(SleeveSizes, CapKeepsSizeMProportionsAndEase) {
  const std::string garment = GetParam();
  const SleeveShape base = sleeve_shape(garment, "M");
  for (const char* size : {"S", "M", "L"}) {
    const SleeveShape s = sleeve_shape(garment, size);
    const double upper_arm_mm = samples::standard_size(size)->upper_arm_mm;
    // At least the upper arm's 70 mm of ease, and at least 0.765 of the armhole it is sewn to.
    EXPECT_GE(s.bicep_mm, upper_arm_mm + 70 - 1e-9) << garment << " " << size;
    EXPECT_GE(s.bicep_mm, 0.765 * s.cap_mm - 1e-9) << garment << " " << size;
    // The cap is no taller for its width than M's (S's was 10 % taller and tangled).
    EXPECT_LE(s.cap_height_mm / s.bicep_mm, base.cap_height_mm / base.bicep_mm * 1.01) << garment << " " << size;
  }
  // M keeps its drafted bicep (the upper arm and 70 mm).
  EXPECT_NEAR(base.bicep_mm, samples::standard_size("M")->upper_arm_mm + 70, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Sleeved, SleeveSizes, ::testing::Values("blouse", "dress"));

}  // namespace
}  // namespace tp::geometry
