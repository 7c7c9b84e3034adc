// tests/host/calibration/calibrate_test.cpp: measurement files are checked with errors naming
// file, line and patch; the chart layout places every patch; a set's manifest is checked.
#include "host/calibration/calibrate.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "host/calibration/chart_layout.h"
#include "host/job/calibration_set.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

// A well-formed RGB measurement file of `n` patches; `bad_row` (1-based) gets `bad_value` as XYZ_Y.
std::string ti3(int n, int bad_row = 0, const std::string& bad_value = "") {
  std::ostringstream o;
  o << "CTI3\nDEVICE_CLASS \"OUTPUT\"\nCOLOR_REP \"RGB_XYZ\"\nBEGIN_DATA_FORMAT\n"
       "SAMPLE_ID RGB_R RGB_G RGB_B XYZ_X XYZ_Y XYZ_Z\nEND_DATA_FORMAT\nNUMBER_OF_SETS "
    << n << "\nBEGIN_DATA\n";
  for (int i = 1; i <= n; ++i)
    o << i << " " << i % 101 << " 50 50 40.1 " << (i == bad_row ? bad_value : "42.0") << " 30.5\n";
  o << "END_DATA\n";
  return o.str();
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(Calibrate, AcceptsAWellFormedMeasurementFile) {
  const auto dir = test::scratch_dir("cal-good");
  auto s = check_measurements(write(dir, "m.ti3", ti3(120)));
  EXPECT_TRUE(s) << s.error().message;
}

TEST(Calibrate, BrokenMeasurementFilesGetClearErrors) {
  const auto dir = test::scratch_dir("cal-bad");
  std::string truncated = ti3(120);
  truncated.resize(truncated.rfind("END_DATA"));  // cut off after a whole row
  const std::pair<std::string, std::string> cases[] = {
      {ti3(120, 7, "abc"), "patch 7: XYZ_Y = 'abc' is not a valid value"},
      {ti3(120, 9, "-5"), "patch 9: XYZ_Y = '-5' is not a valid value"},
      {ti3(40), "40 patches; a profile needs at least 100"},
      {truncated, "BEGIN_DATA without END_DATA"},
      {"CTI1\nBEGIN_DATA_FORMAT\nSAMPLE_ID RGB_R\nEND_DATA_FORMAT\nBEGIN_DATA\n1 0\nEND_DATA\n", "is CTI3, this one is 'CTI1'"},
      {"CTI3\nBEGIN_DATA_FORMAT\nSAMPLE_ID RGB_R RGB_G RGB_B\nEND_DATA_FORMAT\nBEGIN_DATA\n1 0 0 0\nEND_DATA\n",
       "no measured colour"},
      {"garbage that is no CGATS\n", "m.ti3:1: expected a CGATS file identifier"},
  };
  for (const auto& [text, expect] : cases) {
    const auto path = write(dir, "m.ti3", text);
    auto s = check_measurements(path);
    ASSERT_FALSE(s) << expect;
    EXPECT_NE(s.error().message.find(expect), std::string::npos) << s.error().message;
    EXPECT_NE(s.error().message.find("m.ti3"), std::string::npos) << "names the file: " << s.error().message;
  }
}

TEST(Calibrate, CalibrateRefusesABrokenMeasurementFileBeforeRunningColprof) {
  const auto dir = test::scratch_dir("cal-refuse");
  CalibrateOptions o;
  o.out = dir / "set";
  o.measurements = write(dir, "m.ti3", ti3(120, 3, "nan-ish"));
  auto r = calibrate(o);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("patch 3"), std::string::npos) << r.error().message;
  EXPECT_FALSE(fs::exists(dir / "set" / "profile.icc"));
}

TEST(ChartLayout, PlacesEveryPatchInsideTheFrame) {
  device::CgatsTable t;
  t.type = "CTI1";
  t.fields = {"SAMPLE_ID", "RGB_R", "RGB_G", "RGB_B"};
  for (int i = 1; i <= 65; ++i) t.rows.push_back({std::to_string(i), "100", "50", std::to_string(i % 100)});
  auto c = layout_chart(t, "c.ti1");
  ASSERT_TRUE(c) << c.error().message;
  ASSERT_EQ(c->patches.size(), 65u);
  EXPECT_DOUBLE_EQ(c->width_mm, 2 * 6 + 30 * 8);
  EXPECT_DOUBLE_EQ(c->height_mm, 2 * 6 + 3 * 8);
  // Patch 31 starts the second row; its picture pixel has its device values.
  EXPECT_DOUBLE_EQ(c->patches[30].x_mm, 6 + 4);
  EXPECT_DOUBLE_EQ(c->patches[30].y_mm, 6 + 12);
  const auto& px = c->image.at(static_cast<int>(c->patches[30].x_mm * 5), static_cast<int>(c->patches[30].y_mm * 5));
  EXPECT_EQ(px.r, 255);
  EXPECT_NEAR(px.g, 127.5, 0.5);
  EXPECT_EQ(px.b, 79);
  EXPECT_EQ(c->image.at(1, 1).r, 0) << "frame";
  t.rows[4][2] = "120";
  auto bad = layout_chart(t, "c.ti1");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("c.ti1: patch 5: device value '120'"), std::string::npos) << bad.error().message;
}

TEST(CalibrationSet, ManifestIsCheckedAndItsProfileFound) {
  const auto dir = test::scratch_dir("cal-set");
  write(dir, "profile.icc", "not checked here");
  auto good = load_calibration_set(write(dir, "calibration.json",
                                         R"({"format": "tp-calibration/1", "profile": "profile.icc", "fabric": "silk", "patches": 840})"));
  ASSERT_TRUE(good) << good.error().message;
  EXPECT_EQ(good->fabric, "silk");
  EXPECT_EQ(good->profile, dir / "profile.icc");
  const std::pair<std::string, std::string> cases[] = {
      {"{", "not a JSON object"},
      {R"({"format": "other", "profile": "profile.icc"})", "/format"},
      {R"({"format": "tp-calibration/1"})", "/profile: the set names no profile"},
      {R"({"format": "tp-calibration/1", "profile": "../profile.icc"})", "inside the set's folder"},
      {R"({"format": "tp-calibration/1", "profile": "gone.icc"})", "does not exist"},
  };
  for (const auto& [text, expect] : cases) {
    auto r = load_calibration_set(write(dir, "calibration.json", text));
    ASSERT_FALSE(r) << text;
    EXPECT_NE(r.error().message.find(expect), std::string::npos) << r.error().message;
  }
}

}  // namespace
}  // namespace tp::host
