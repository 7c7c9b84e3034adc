// tests/host/calibration/light_chart_test.cpp: the light-colour chart covers the light corner of
// device RGB on a regular grid, bare fabric included, in the CTI1 form the chart printer reads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <tuple>

#include "host/calibration/light_chart.h"

namespace tp::host {
namespace {

TEST(LightChart, IsTheLightCornerGridOfDeviceRgb) {
  const device::CgatsTable t = light_chart();
  EXPECT_EQ(t.type, "CTI1");
  ASSERT_EQ(t.fields, (std::vector<std::string>{"SAMPLE_ID", "RGB_R", "RGB_G", "RGB_B"}));
  ASSERT_EQ(t.rows.size(), 343u);
  std::set<std::tuple<double, double, double>> seen;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& row = t.rows[i];
    ASSERT_EQ(row.size(), 4u);
    EXPECT_EQ(row[0], std::to_string(i + 1));
    double v[3];
    for (int c = 0; c < 3; ++c) {
      v[c] = std::strtod(row[static_cast<std::size_t>(c) + 1].c_str(), nullptr);
      EXPECT_GE(v[c], 100 * kLightChartFrom - 1e-9) << "patch " << i + 1;
      EXPECT_LE(v[c], 100.0) << "patch " << i + 1;
      // On the grid: a whole number of steps from the lowest value.
      const double steps = (v[c] / 100 - kLightChartFrom) / kLightChartStep;
      EXPECT_NEAR(steps, std::round(steps), 1e-6) << "patch " << i + 1;
    }
    EXPECT_TRUE(seen.insert({v[0], v[1], v[2]}).second) << "patch " << i + 1 << " repeats another";
  }
  // The bare fabric (the media white) and the corner's darkest grey are both on it.
  EXPECT_TRUE(seen.count({100.0, 100.0, 100.0}));
  EXPECT_TRUE(seen.count({70.0, 70.0, 70.0}));
}

}  // namespace
}  // namespace tp::host
