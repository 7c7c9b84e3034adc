// tests/rip/colour/ink_converter_test.cpp: the sRGB-to-ink table against the profile's own
// prediction (dE00), the ink limit, partial coverage, linearisation and profile errors.
#include "rip/colour/ink_converter.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <lcms2.h>

namespace tp::rip {
namespace {

using geometry::Rgba8;

/// What the printer profile says an ink combination looks like (its AToB1 table), Lab D50.
class ProfilePrediction {
 public:
  explicit ProfilePrediction(int inks) {
    prof_ = cmsOpenProfileFromFile(kDefaultCmykProfilePath, "r");
    lab_ = cmsCreateLab4Profile(nullptr);
    xf_ = cmsCreateTransform(prof_, CHANNELS_SH(inks) | BYTES_SH(0) | FLOAT_SH(1), lab_, TYPE_Lab_DBL,
                             INTENT_RELATIVE_COLORIMETRIC, cmsFLAGS_NOOPTIMIZE);
  }
  ~ProfilePrediction() {
    cmsDeleteTransform(xf_);
    cmsCloseProfile(lab_);
    cmsCloseProfile(prof_);
  }
  bool ok() const { return xf_ != nullptr; }
  cmsCIELab lab(const std::vector<double>& ink) const {
    cmsCIELab out;
    cmsDoTransform(xf_, ink.data(), &out, 1);
    return out;
  }

 private:
  cmsHPROFILE prof_, lab_;
  cmsHTRANSFORM xf_;
};

std::vector<double> table_inks(const InkConverter& conv, Rgba8 c) {
  std::vector<std::uint8_t> out(static_cast<size_t>(conv.channels()));
  std::vector<std::uint8_t*> planes;
  for (auto& o : out) planes.push_back(&o);
  conv.convert_row(&c, 1, planes.data());
  std::vector<double> ink;
  for (auto o : out) ink.push_back(o / 255.0);
  return ink;
}

std::vector<Rgba8> patch_chart() {
  std::vector<Rgba8> chart;
  for (int r = 0; r < 6; ++r)
    for (int g = 0; g < 6; ++g)
      for (int b = 0; b < 6; ++b)
        chart.push_back({static_cast<std::uint8_t>(r * 51), static_cast<std::uint8_t>(g * 51),
                         static_cast<std::uint8_t>(b * 51), 255});
  for (int v = 0; v < 256; v += 15) chart.push_back({static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v),
                                                      static_cast<std::uint8_t>(v), 255});
  std::mt19937 rng(11);
  for (int i = 0; i < 200; ++i)
    chart.push_back({static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()), 255});
  return chart;
}

TEST(InkConverter, PatchChartLandsWithinDeltaE2OfTheProfile) {
  for (double limit : {0.0, 300.0}) {
    InkConverterSettings s;
    s.ink_limit_percent = limit;
    auto conv = InkConverter::create(s);
    ASSERT_TRUE(conv) << conv.error().what();
    ProfilePrediction pred(4);
    ASSERT_TRUE(pred.ok());
    double worst = 0, sum = 0;
    const auto chart = patch_chart();
    for (Rgba8 c : chart) {
      // The profile's prediction for the exact separation versus for the table's 8-bit inks.
      cmsCIELab want = pred.lab(conv->convert_exact(c)), got = pred.lab(table_inks(*conv, c));
      const double de = cmsCIE2000DeltaE(&want, &got, 1, 1, 1);
      worst = std::max(worst, de);
      sum += de;
    }
    EXPECT_LE(worst, 2.0) << "limit " << limit;
    EXPECT_LE(sum / chart.size(), 0.5) << "limit " << limit;
    RecordProperty(limit > 0 ? "worst_de00_limited" : "worst_de00", std::to_string(worst));
  }
}

TEST(InkConverter, ACalibrationProfileMustBeAnRgbOutputProfile) {
  if (!std::filesystem::exists(kDefaultCmykProfilePath)) GTEST_SKIP();
  InkConverterSettings s;
  s.calibration_profile = kDefaultCmykProfilePath;
  auto c = InkConverter::create(s);
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("must be an RGB output profile"), std::string::npos) << c.error().message;
  s.calibration_profile = "/nonexistent/cal.icc";
  c = InkConverter::create(s);
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("/nonexistent/cal.icc"), std::string::npos) << c.error().message;
}

TEST(InkConverter, TotalInkNeverExceedsTheLimit) {
  InkConverterSettings s;
  s.ink_limit_percent = 240;
  auto conv = InkConverter::create(s);
  ASSERT_TRUE(conv);
  const int limit = conv->ink_limit_8bit();
  EXPECT_EQ(limit, 240 * 255 / 100);
  std::mt19937 rng(3);
  std::vector<Rgba8> row(4096);
  for (auto& p : row)
    p = {static_cast<std::uint8_t>(rng() % 64), static_cast<std::uint8_t>(rng() % 64), static_cast<std::uint8_t>(rng() % 64),
         static_cast<std::uint8_t>(rng() % 2 ? 255 : rng())};
  row[0] = {0, 0, 0, 255};
  std::vector<std::vector<std::uint8_t>> out(4, std::vector<std::uint8_t>(row.size()));
  std::uint8_t* planes[4] = {out[0].data(), out[1].data(), out[2].data(), out[3].data()};
  conv->convert_row(row.data(), static_cast<int>(row.size()), planes);
  int max_sum = 0;
  for (size_t i = 0; i < row.size(); ++i) {
    const int sum = out[0][i] + out[1][i] + out[2][i] + out[3][i];
    ASSERT_LE(sum, limit) << "pixel " << i;
    max_sum = std::max(max_sum, sum);
  }
  // Black is dark enough to need the limit: it must be reached, not undercut by far.
  EXPECT_GE(max_sum, limit - 8);
  // Without a limit the same black uses more ink than the limit allows.
  auto free = InkConverter::create(InkConverterSettings{});
  ASSERT_TRUE(free);
  auto ink = table_inks(*free, {0, 0, 0, 255});
  EXPECT_GT((ink[0] + ink[1] + ink[2] + ink[3]) * 255, limit + 10);
}

TEST(InkConverter, CoverageScalesInksAndTransparentIsBlank) {
  auto conv = InkConverter::create(InkConverterSettings{});
  ASSERT_TRUE(conv);
  Rgba8 row[3] = {{20, 90, 160, 255}, {20, 90, 160, 128}, {20, 90, 160, 0}};
  std::uint8_t out[4][3];
  std::uint8_t* planes[4] = {out[0], out[1], out[2], out[3]};
  EXPECT_TRUE(conv->convert_row(row, 3, planes));
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(out[c][1], out[c][0] * 128 / 255.0, 1.0) << c;
    EXPECT_LE(out[c][1], out[c][0] * 128 / 255.0 + 1e-9) << c;
    EXPECT_EQ(out[c][2], 0);
  }
  EXPECT_GT(out[0][0], 100);  // a strong blue needs cyan
  Rgba8 clear[2] = {{0, 0, 0, 0}, {255, 0, 0, 0}};
  EXPECT_FALSE(conv->convert_row(clear, 2, planes));
}

TEST(InkConverter, LinearisationCurvesShapeEachInk) {
  InkConverterSettings s;
  // Cyan halved everywhere (a dot-gain-heavy ink), others untouched.
  s.linearisation = {ToneCurve{{{0, 0}, {1, 0.5}}}, {}, {}, {}};
  auto lin = InkConverter::create(s);
  auto plain = InkConverter::create(InkConverterSettings{});
  ASSERT_TRUE(lin && plain);
  const Rgba8 c{40, 120, 200, 255};
  auto a = table_inks(*plain, c), b = table_inks(*lin, c);
  EXPECT_NEAR(b[0], a[0] / 2, 2.5 / 255);
  EXPECT_NEAR(b[1], a[1], 1.5 / 255);
}

TEST(InkConverter, DeviceInksPrintTheDesignChannelsAsInkAmounts) {
  InkConverterSettings s;
  s.device_inks = {"black", "cyan"};  // R drives black, G cyan; magenta and yellow never print
  s.ink_limit_percent = 150;          // off for device values: a chart must print as asked
  auto conv = InkConverter::create(s);
  ASSERT_TRUE(conv) << conv.error().message;
  for (const Rgba8 c : {Rgba8{0, 0, 0, 255}, Rgba8{255, 128, 7, 255}, Rgba8{51, 204, 255, 255}}) {
    const auto exact = conv->convert_exact(c);
    const auto table = table_inks(*conv, c);
    EXPECT_NEAR(exact[3], 1 - c.r / 255.0, 1e-9);
    EXPECT_NEAR(exact[0], 1 - c.g / 255.0, 1e-9);
    EXPECT_EQ(exact[1], 0);
    EXPECT_EQ(exact[2], 0);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(table[k], exact[k], 0.6 / 255) << k;
  }
  // The curves still apply: cyan laid at most 80 %.
  s.linearisation = {ToneCurve{{{0, 0}, {1, 0.8}}}, {}, {}, {}};
  auto lin = InkConverter::create(s);
  ASSERT_TRUE(lin);
  EXPECT_NEAR(lin->convert_exact({255, 0, 255, 255})[0], 0.8, 1e-9);
}

TEST(InkConverter, DeviceInksErrorsNameTheInk) {
  InkConverterSettings s;
  s.device_inks = {"cyan", "orange"};
  auto a = InkConverter::create(s);
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("'orange' is not one of the printer's inks"), std::string::npos)
      << a.error().message;
  s.device_inks = {"cyan", "cyan"};
  auto b = InkConverter::create(s);
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().message.find("'cyan' twice"), std::string::npos) << b.error().message;
  s.device_inks = {"cyan", "magenta", "yellow", "black"};
  EXPECT_FALSE(InkConverter::create(s));
}

TEST(InkConverter, ProfileErrorsNameTheFile) {
  InkConverterSettings missing;
  missing.profile_path = "/nonexistent/printer.icc";
  auto a = InkConverter::create(missing);
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("/nonexistent/printer.icc"), std::string::npos);

  InkConverterSettings rgb;  // an RGB display profile is not a printer profile
  rgb.profile_path = "/usr/share/ghostscript/10.00.0/iccprofiles/srgb.icc";
  auto b = InkConverter::create(rgb);
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().message.find("srgb.icc"), std::string::npos) << b.error().message;

  InkConverterSettings six;  // CMYK profile for a six-ink printer
  six.profile_path = kDefaultCmykProfilePath;
  six.ink_names = {"cyan", "magenta", "yellow", "black", "red", "blue"};
  auto c = InkConverter::create(six);
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("4 colourants"), std::string::npos) << c.error().message;

  InkConverterSettings unknown_ink;  // no profile and an ink without a typical colour
  unknown_ink.ink_names = {"cyan", "magenta", "yellow", "black", "sparkle"};
  auto d = InkConverter::create(unknown_ink);
  ASSERT_FALSE(d);
  EXPECT_NE(d.error().message.find("'sparkle'"), std::string::npos) << d.error().message;

  InkConverterSettings bad_limit;
  bad_limit.ink_limit_percent = 50;
  EXPECT_FALSE(InkConverter::create(bad_limit));
}

// The table of every colour gives the per-pixel interpolation's inks for all 2^24 colours, at
// full coverage and partial coverage, with an ink limit, whatever the row's length (the 16-pixel
// transposition and its tail). Also with a three-ink printer (the packed path without transposition).
TEST(InkConverter, DirectTableEqualsInterpolationForEveryColour) {
  for (const auto& inks : {std::vector<std::string>{"cyan", "magenta", "yellow", "black"},
                           std::vector<std::string>{"cyan", "magenta", "yellow"}}) {
    InkConverterSettings s;
    s.ink_names = inks;
    s.ink_limit_percent = 260;
    auto plain = InkConverter::create(s);
    s.direct_table = true;
    auto direct = InkConverter::create(s);
    ASSERT_TRUE(plain && direct) << (plain ? direct.error().what() : plain.error().what());
    const int nc = static_cast<int>(inks.size());
    constexpr int kRow = 65536 + 7;
    std::vector<Rgba8> row(kRow);
    std::vector<std::vector<std::uint8_t>> a(static_cast<size_t>(nc), std::vector<std::uint8_t>(kRow)),
        b(static_cast<size_t>(nc), std::vector<std::uint8_t>(kRow));
    std::vector<std::uint8_t*> pa, pb;
    for (int c = 0; c < nc; ++c) pa.push_back(a[static_cast<size_t>(c)].data()), pb.push_back(b[static_cast<size_t>(c)].data());
    for (std::uint32_t base = 0; base < (1u << 24); base += 65536) {
      for (int i = 0; i < kRow; ++i) {
        const std::uint32_t key = (base + static_cast<std::uint32_t>(i)) & 0xffffffu;
        // Mostly opaque runs (the transposed path) with a partly covered pixel now and then.
        const std::uint8_t alpha = i % 97 == 0 ? static_cast<std::uint8_t>(i % 256) : 255;
        row[static_cast<size_t>(i)] = {static_cast<std::uint8_t>(key), static_cast<std::uint8_t>(key >> 8),
                                       static_cast<std::uint8_t>(key >> 16), alpha};
      }
      const int n = kRow - static_cast<int>(base / 65536 % 16);  // tails of every length
      EXPECT_EQ(plain->convert_row(row.data(), n, pa.data()), direct->convert_row(row.data(), n, pb.data()));
      for (int c = 0; c < nc; ++c)
        for (int i = 0; i < n; ++i)
          ASSERT_EQ(a[static_cast<size_t>(c)][static_cast<size_t>(i)], b[static_cast<size_t>(c)][static_cast<size_t>(i)])
              << inks.size() << " inks, ink " << c << ", pixel " << base + static_cast<std::uint32_t>(i);
    }
  }
}

}  // namespace
}  // namespace tp::rip
