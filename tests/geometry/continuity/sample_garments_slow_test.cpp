// tests/geometry/continuity/sample_garments_slow_test.cpp: the paper's four garments with their
// designs meet issue 5's figures at 150 dpi: seam dE00 mean <= 1.0 and p95 <= 2.5, allowance copy
// p95 <= 2.5. Slow: each garment is drafted and sewn on its dress form first.
#include <gtest/gtest.h>

#include "geometry/continuity/continuity.h"
#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/sample_designs.h"
#include "geometry/samples/garments.h"

namespace tp::geometry {
namespace {

class SampleGarment : public ::testing::TestWithParam<const char*> {};

TEST_P(SampleGarment, SeamsAndAllowancesMeetTheFigures) {
  auto sample = samples::make_garment(GetParam(), "M");
  ASSERT_TRUE(sample) << sample.error().what();
  Finishing f;
  f.job_name = "TEST";
  auto r = make_piece_renderer(sample->pattern, sample->garment, sample_design(GetParam(), sample->garment), f);
  ASSERT_TRUE(r) << r.error().what();
  auto rep = measure_continuity(sample->pattern, sample->garment, f, **r, 150);
  ASSERT_TRUE(rep) << rep.error().what();
  EXPECT_GT(rep->seams.samples, 5000u);
  EXPECT_GT(rep->allowance.samples, 20000u);
  EXPECT_LE(rep->seams.mean, 1.0);
  EXPECT_LE(rep->seams.p95, 2.5);
  EXPECT_LE(rep->allowance.p95, 2.5);
  // Every stitched seam of the pattern is measured.
  EXPECT_GE(rep->seam_list.size(), sample->pattern.stitches.size() / 2);
}

INSTANTIATE_TEST_SUITE_P(Paper, SampleGarment, ::testing::Values("skirt8", "simple_top", "blouse", "dress"));

}  // namespace
}  // namespace tp::geometry
