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
  // The ink charts came first: a drop limit and a monotone curve ending at it per ink, a limit.
  EXPECT_EQ(m["ink_charts"].get<int>(), 7) << "2 drop-limit, 4 linearisation, 1 ink-limit chart";
  ASSERT_EQ(m["inks"].size(), 4u);
  for (const auto& ink : m["inks"]) {
    const double d = ink["drop_limit"].get<double>();
    EXPECT_GT(d, 0.3) << ink.dump();
    EXPECT_LE(d, 1.0) << ink.dump();
    const auto& curve = ink["linearisation"];
    ASSERT_GE(curve.size(), 2u);
    for (size_t k = 1; k < curve.size(); ++k)
      EXPECT_GE(curve[k][1].get<double>(), curve[k - 1][1].get<double>()) << ink.dump();
    EXPECT_NEAR(curve.back()[1].get<double>(), 100 * d, 0.01);
  }
  const double limit = m["ink_limit_percent"].get<double>();
  EXPECT_GE(limit, 100);
  EXPECT_LE(limit, 300);
  // The profiling chart printed through them: its job names the set without a profile.
  std::ifstream chart_set(out / "chart-job" / "calibration.json");
  const auto set = nlohmann::json::parse(chart_set);
  EXPECT_TRUE(set["profile"].is_null());
  EXPECT_EQ(set["ink_limit_percent"].get<double>(), limit);
  EXPECT_EQ(set["inks"], m["inks"]);
}

}  // namespace
}  // namespace tp::test
