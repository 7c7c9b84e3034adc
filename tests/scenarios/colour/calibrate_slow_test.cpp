// tests/scenarios/colour/calibrate_slow_test.cpp: `printctl calibrate` end to end on printsim:
// a targen chart printed through the job path, read by the simulated spectrophotometer, profiled
// by colprof; the set's manifest and profile are there and the profile fits its measurements.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

TEST(Calibrate, PrintsMeasuresAndProfilesAChartOnTheSimulator) {
  const fs::path out = scratch_dir("calibrate-e2e") / "set";
  auto r = run_command({(bin_dir() / "printctl").string(), "calibrate", "--fabric", "silk", "--out", out.string(),
                        "--quality", "l", "--noise", "0.1"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(out / "calibration.json");
  const auto m = nlohmann::json::parse(in);
  EXPECT_EQ(m["format"], "tp-calibration/1");
  EXPECT_EQ(m["fabric"], "silk");
  EXPECT_GE(m["patches"].get<int>(), 800);
  EXPECT_GT(m["chart_area_m2"].get<double>(), 0.03);
  EXPECT_TRUE(fs::is_regular_file(out / "profile.icc"));
  // A chart read at the wrong place would not fit a smooth profile.
  EXPECT_GT(m["fit_de00"]["mean"].get<double>(), 0.0);
  EXPECT_LT(m["fit_de00"]["mean"].get<double>(), 1.5) << m.dump();
  EXPECT_TRUE(fs::exists(out / "chart-printed" / "fabric-lab.tif"));
}

}  // namespace
}  // namespace tp::test
