// tests/geometry/samples/sample_sizes_slow_test.cpp: every sample garment, sewn in S, M and L at
// the 15 mm mesh orders use, passes the fit checks (untangled, nothing inside the dress form).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>

#include "geometry/garment/fit_checks.h"
#include "geometry/samples/garments.h"

namespace tp::geometry {
namespace {

class SampleSizes : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(SampleSizes, SewnGarmentPassesTheFitChecks) {
  const auto& [garment, size] = GetParam();
  SewOptions o;
  o.target_edge_mm = 15;
  auto g = samples::make_garment(garment, size, o);
  ASSERT_TRUE(g) << g.error().what();
  const FitReport fit = check_fit(g->pattern, g->garment, g->body.get(), g->stats.stitch_gap_mm);
  std::printf(
      "figure garment=%s size=%s triangles=%d self_intersections=%d inside_body=%d body_crossings=%d "
      "stitch_gap_max_mm=%.2f\n",
      garment.c_str(), size.c_str(), fit.triangles, fit.self_intersections, fit.inside_body, fit.body_crossings,
      fit.stitch_gap_max_mm);
  std::string failed;
  for (const auto& f : fit.failures) failed += f.message + "; ";
  EXPECT_TRUE(fit.pass) << garment << " " << size << ": " << failed;
  EXPECT_EQ(fit.inside_body, 0) << garment << " " << size;
  EXPECT_LT(fit.self_intersections, 0.002 * fit.triangles) << garment << " " << size;
}

INSTANTIATE_TEST_SUITE_P(Table2, SampleSizes,
                         ::testing::Combine(::testing::Values("simple_top", "blouse", "dress", "skirt8"),
                                            ::testing::Values("S", "M", "L")));

}  // namespace
}  // namespace tp::geometry
