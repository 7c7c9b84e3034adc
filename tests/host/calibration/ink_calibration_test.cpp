// tests/host/calibration/ink_calibration_test.cpp: drop limit, linearisation and ink limit from
// measured ramps; device-chart readings and calibration sets with curves checked with clear
// errors; a set's curves and limit applied by the separation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "host/calibration/device_readings.h"
#include "host/calibration/drop_limit.h"
#include "host/calibration/ink_limit.h"
#include "host/calibration/linearisation.h"
#include "host/job/calibration_set.h"
#include "rip/colour/ink_converter.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

// A cyan-like ramp: the fabric at L* 94, darkening with dot gain (1 - (1 - x)^2) until the ink
// stops taking at `saturates` (more ink changes nothing).
std::vector<RampPoint> ramp(double saturates, double step, double noise = 0, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0, noise > 0 ? noise : 1);
  std::vector<RampPoint> out;
  for (int i = 0; i * step <= 1 + 1e-9; ++i) {
    const double x = i * step, e = std::min(x, saturates) / saturates;
    const double tone = 1 - (1 - e) * (1 - e);
    device::Lab lab{94 - 40 * tone, -2 - 35 * tone, -4 - 40 * tone};
    if (noise > 0 && i > 0) lab = {lab.l + noise * n(rng), lab.a + noise * n(rng), lab.b + noise * n(rng)};
    out.push_back({x, lab});
  }
  return out;
}

TEST(DropLimit, FindsWhereTheInkStopsChangingColour) {
  auto d = drop_limit(ramp(0.8, 0.025), "cyan");
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_GT(*d, 0.60);  // the last 1 dE00 of a dot-gain ramp spans its top fifth
  EXPECT_LE(*d, 0.80 + 1e-9);
  auto looser = drop_limit(ramp(0.8, 0.025), "cyan", 3.0);  // within 3 dE00: less ink
  ASSERT_TRUE(looser);
  EXPECT_LT(*looser, *d);
  EXPECT_FALSE(drop_limit(ramp(0.8, 0.025), "cyan", 0));
  auto none = drop_limit(ramp(2.0, 0.05), "cyan");  // never saturates: the heaviest patch
  ASSERT_TRUE(none);
  EXPECT_GT(*none, 0.9);
}

TEST(DropLimit, RefusesRampsItCannotRead) {
  auto flat = ramp(0.8, 0.05);
  for (auto& p : flat) p.lab = flat.front().lab;
  auto a = drop_limit(flat, "yellow");
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("ink 'yellow'"), std::string::npos);
  EXPECT_NE(a.error().message.find("does not print"), std::string::npos) << a.error().message;
  auto short_ramp = ramp(0.8, 0.05);
  short_ramp.resize(10);  // up to 45 %
  EXPECT_FALSE(drop_limit(short_ramp, "cyan"));
  auto no_white = ramp(0.8, 0.05);
  no_white.erase(no_white.begin());
  EXPECT_FALSE(drop_limit(no_white, "cyan"));
}

TEST(Linearisation, CurvesAreMonotoneAndEndAtTheDropLimit) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    auto c = linearisation_curve(ramp(1.0, 0.05, 0.4, seed), 0.85, "cyan");
    ASSERT_TRUE(c) << c.error().message;
    ASSERT_EQ(c->points.size(), static_cast<size_t>(kLinearisationSteps + 1));
    EXPECT_TRUE(rip::validate_tone_curve(*c, "curve"));
    for (size_t i = 1; i < c->points.size(); ++i) EXPECT_GE(c->points[i].second, c->points[i - 1].second) << seed;
    EXPECT_EQ(c->points.front().second, 0);
    EXPECT_DOUBLE_EQ(c->points.back().second, 0.85);
  }
  // Without noise it inverts the dot gain: half the tone needs 1 - sqrt(0.5) of the ramp.
  auto c = linearisation_curve(ramp(1.0, 0.05), 0.85, "cyan");
  ASSERT_TRUE(c);
  EXPECT_NEAR(rip::evaluate(*c, 0.5), (1 - std::sqrt(0.5)) * 0.85, 0.01);
}

TEST(Linearisation, RefusesBadRampsNamingTheInk) {
  auto a = linearisation_curve(ramp(1.0, 0.05), 1.5, "magenta");
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("ink 'magenta'"), std::string::npos);
  auto part = ramp(1.0, 0.05);
  part.pop_back();
  auto b = linearisation_curve(part, 0.9, "magenta");
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().message.find("stops short of 100 %"), std::string::npos) << b.error().message;
}

TEST(InkLimit, FindsTheTotalPastWhichOverprintsNoLongerDarken) {
  std::vector<RampPoint> r;
  for (double t = 0.9; t <= 2.7 + 1e-9; t += 0.15) r.push_back({t, {60 - 25 * std::min(t, 2.2), 0, 0}});
  auto limit = ink_limit_percent(r);
  ASSERT_TRUE(limit) << limit.error().message;
  EXPECT_GE(*limit, 200);
  EXPECT_LE(*limit, 220);
  EXPECT_EQ(std::fmod(*limit, 5), 0);
  r.resize(2);
  EXPECT_FALSE(ink_limit_percent(r));
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(DeviceReadings, ReadsRampsAndNamesBrokenPatches) {
  const auto dir = test::scratch_dir("device-readings");
  const std::string head =
      "CTI3\nBEGIN_DATA_FORMAT\nSAMPLE_ID RGB_R RGB_G RGB_B XYZ_X XYZ_Y XYZ_Z\nEND_DATA_FORMAT\nBEGIN_DATA\n";
  auto good = read_device_readings(write(dir, "m.ti3",
                                         head + "1 100 100 100 80 85 70\n2 100 100 100 80 85 70\n"
                                                "3 50 100 100 40 50 60\n4 50 100 100 42 52 62\n"
                                                "5 100 50 100 50 30 40\n6 0 100 100 10 20 40\nEND_DATA\n"));
  ASSERT_TRUE(good) << good.error().message;
  auto r = single_channel_ramp(*good, 0);
  ASSERT_EQ(r.size(), 3u);  // 0, 0.5 (two replicates averaged), 1; the magenta patch is not cyan's
  EXPECT_EQ(r[0].amount, 0);
  EXPECT_NEAR(r[1].amount, 0.5, 1e-12);
  EXPECT_EQ(r[2].amount, 1);
  const std::pair<std::string, std::string> cases[] = {
      {head + "1 100 100 100 80 abc 70\nEND_DATA\n", "patch 1: XYZ_Y = 'abc' is not a valid value"},
      {head + "7 100 120 100 80 85 70\nEND_DATA\n", "patch 7: RGB_G = '120' is not a valid value"},
      {"CTI3\nBEGIN_DATA_FORMAT\nSAMPLE_ID RGB_R RGB_G XYZ_X XYZ_Y XYZ_Z\nEND_DATA_FORMAT\nBEGIN_DATA\n1 0 0 1 1 "
       "1\nEND_DATA\n",
       "field RGB_B missing"},
      {head + "1 100 100\nEND_DATA\n", "m.ti3:6"},
  };
  for (const auto& [text, expect] : cases) {
    auto bad = read_device_readings(write(dir, "m.ti3", text));
    ASSERT_FALSE(bad) << expect;
    EXPECT_NE(bad.error().message.find(expect), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("m.ti3"), std::string::npos) << bad.error().message;
  }
}

TEST(CalibrationSet, ReadsCurvesAndLimitAndRefusesBrokenOnes) {
  const auto dir = test::scratch_dir("cal-set-inks");
  auto set = load_calibration_set(write(dir, "calibration.json", R"({"format": "tp-calibration/1", "profile": null,
      "inks": [{"name": "cyan", "drop_limit": 0.8, "linearisation": [[0, 0], [50, 30], [100, 80]]}],
      "ink_limit_percent": 240})"));
  ASSERT_TRUE(set) << set.error().message;
  EXPECT_TRUE(set->profile.empty());
  ASSERT_EQ(set->inks.size(), 1u);
  EXPECT_DOUBLE_EQ(set->inks[0].linearisation.points[1].second, 0.3);
  EXPECT_EQ(set->ink_limit_percent, 240);
  const std::pair<std::string, std::string> cases[] = {
      {R"({"format": "tp-calibration/1", "profile": null, "inks": [{"name": "cyan",
          "linearisation": [[0, 0], [50, 60], [100, 40]]}]})",
       "/inks/0/linearisation: point 3: output 40 % decreases"},
      {R"({"format": "tp-calibration/1", "profile": null, "inks": [{"drop_limit": 0.8}]})", "/inks/0/name"},
      {R"({"format": "tp-calibration/1", "profile": null, "inks": [{"name": "k", "drop_limit": 2}]})",
       "/inks/0/drop_limit"},
      {R"({"format": "tp-calibration/1", "profile": null, "ink_limit_percent": 50})", "/ink_limit_percent"},
      {R"({"format": "tp-calibration/1", "profile": null})", "names no profile, curves or ink limit"},
  };
  for (const auto& [text, expect] : cases) {
    auto bad = load_calibration_set(write(dir, "calibration.json", text));
    ASSERT_FALSE(bad) << expect;
    EXPECT_NE(bad.error().message.find(expect), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("calibration.json"), std::string::npos) << bad.error().message;
  }
}

TEST(CalibrationSet, ItsCurvesAndLimitAreAppliedByTheSeparation) {
  CalibrationSet set;
  set.inks = {{"magenta", 0.7, rip::ToneCurve{{{0, 0}, {1, 0.7}}}}, {"cyan", 0.9, rip::ToneCurve{{{0, 0}, {1, 0.9}}}}};
  set.ink_limit_percent = 200;
  rip::InkConverterSettings s;  // the printer's order: cyan, magenta, yellow, black
  s.linearisation = linearisation_for(set, s.ink_names);
  ASSERT_EQ(s.linearisation.size(), 4u);
  EXPECT_TRUE(s.linearisation[2].points.empty());  // yellow: not in the set, unchanged
  s.ink_limit_percent = set.ink_limit_percent;
  auto conv = rip::InkConverter::create(s);
  ASSERT_TRUE(conv) << conv.error().message;
  for (const geometry::Rgba8 c : {geometry::Rgba8{0, 0, 0, 255}, geometry::Rgba8{0, 255, 255, 255},
                                  geometry::Rgba8{255, 0, 255, 255}, geometry::Rgba8{30, 20, 60, 255}}) {
    const auto ink = conv->convert_exact(c);
    double sum = 0;
    for (double v : ink) sum += v;
    EXPECT_LE(sum, 2.0 + 1e-9) << int(c.r) << "," << int(c.g) << "," << int(c.b);
    EXPECT_LE(ink[0], 0.9 + 1e-9);
    EXPECT_LE(ink[1], 0.7 + 1e-9);
  }
}

}  // namespace
}  // namespace tp::host
