// tests/rip/colour/profile_inverse_test.cpp: the inverse of an RGB output profile reaches its
// forward model where the profile's own coarse B2A table does not, and clips outside the gamut.
#include "rip/colour/profile_inverse.h"

#include <gtest/gtest.h>
#include <lcms2.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include <unistd.h>

namespace tp::rip {
namespace {

// A printer-like forward model: each channel with its own tone response, a dull white.
device::Lab forward_model(double r, double g, double b) {
  const double lr = std::pow(r, 2.2), lg = std::pow(g, 1.6), lb = std::pow(b, 2.8);
  const device::Xyz xyz{0.03 + 0.92 * (0.4360747 * lr + 0.3850649 * lg + 0.1430804 * lb),
                        0.03 + 0.92 * (0.2225045 * lr + 0.7168786 * lg + 0.0606169 * lb),
                        0.03 + 0.92 * (0.0139322 * lr + 0.0971045 * lg + 0.7141733 * lb)};
  return device::xyz_to_lab(xyz);
}

int forward_sampler(const cmsUInt16Number in[], cmsUInt16Number out[], void*) {
  const device::Lab lab = forward_model(in[0] / 65535.0, in[1] / 65535.0, in[2] / 65535.0);
  const cmsCIELab c{lab.l, lab.a, lab.b};
  cmsFloat2LabEncoded(out, &c);
  return 1;
}

// A deliberately crude inverse on a coarse grid: one gamma for all channels.
int backward_sampler(const cmsUInt16Number in[], cmsUInt16Number out[], void*) {
  cmsCIELab lab;
  cmsLabEncoded2Float(&lab, in);
  const device::Xyz xyz = device::lab_to_xyz({lab.L, lab.a, lab.b});
  const double m[3][3] = {
      {3.1338561, -1.6168667, -0.4906146}, {-0.9787684, 1.9161415, 0.0334540}, {0.0719453, -0.2289914, 1.4052427}};
  const double v[3] = {(xyz.x - 0.03) / 0.92, (xyz.y - 0.03) / 0.92, (xyz.z - 0.03) / 0.92};
  for (int c = 0; c < 3; ++c) {
    const double lin = std::clamp(m[c][0] * v[0] + m[c][1] * v[1] + m[c][2] * v[2], 0.0, 1.0);
    out[c] = static_cast<cmsUInt16Number>(std::lround(std::pow(lin, 1 / 2.2) * 65535.0));
  }
  return 1;
}

std::filesystem::path write_profile(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".icc");
  cmsHPROFILE p = cmsCreateProfilePlaceholder(nullptr);
  cmsSetProfileVersion(p, 4.3);
  cmsSetDeviceClass(p, cmsSigOutputClass);
  cmsSetColorSpace(p, cmsSigRgbData);
  cmsSetPCS(p, cmsSigLabData);
  cmsPipeline* a2b = cmsPipelineAlloc(nullptr, 3, 3);
  cmsStage* fwd = cmsStageAllocCLut16bit(nullptr, 33, 3, 3, nullptr);
  cmsStageSampleCLut16bit(fwd, forward_sampler, nullptr, 0);
  cmsPipelineInsertStage(a2b, cmsAT_BEGIN, fwd);
  cmsPipelineInsertStage(a2b, cmsAT_BEGIN, cmsStageAllocToneCurves(nullptr, 3, nullptr));
  cmsPipelineInsertStage(a2b, cmsAT_END, cmsStageAllocToneCurves(nullptr, 3, nullptr));
  cmsPipeline* b2a = cmsPipelineAlloc(nullptr, 3, 3);
  cmsStage* bwd = cmsStageAllocCLut16bit(nullptr, 9, 3, 3, nullptr);
  cmsStageSampleCLut16bit(bwd, backward_sampler, nullptr, 0);
  cmsPipelineInsertStage(b2a, cmsAT_BEGIN, bwd);
  cmsPipelineInsertStage(b2a, cmsAT_BEGIN, cmsStageAllocToneCurves(nullptr, 3, nullptr));
  cmsPipelineInsertStage(b2a, cmsAT_END, cmsStageAllocToneCurves(nullptr, 3, nullptr));
  for (cmsTagSignature t : {cmsSigAToB0Tag, cmsSigAToB1Tag}) cmsWriteTag(p, t, a2b);
  for (cmsTagSignature t : {cmsSigBToA0Tag, cmsSigBToA1Tag}) cmsWriteTag(p, t, b2a);
  cmsWriteTag(p, cmsSigMediaWhitePointTag, cmsD50_XYZ());
  EXPECT_TRUE(cmsSaveProfileToFile(p, path.c_str()));
  cmsPipelineFree(a2b);
  cmsPipelineFree(b2a);
  cmsCloseProfile(p);
  return path;
}

TEST(RgbProfileInverse, ReachesTheForwardModelWhereTheB2ATableMissesIt) {
  const auto path = write_profile("tp_inverse_reach");
  auto inv = RgbProfileInverse::open(path);
  ASSERT_TRUE(inv) << inv.error().message;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.02, 0.98);
  std::vector<std::array<double, 3>> rgb(300);
  for (auto& v : rgb) v = {u(rng), u(rng), u(rng)};
  const std::vector<device::Lab> targets = inv->colour_of(rgb);
  const std::vector<device::Lab> got = inv->colour_of(inv->device_for(targets));

  // The profile's own B2A table, for comparison.
  cmsHPROFILE prof = cmsOpenProfileFromFile(path.c_str(), "r"), lab = cmsCreateLab4Profile(nullptr);
  cmsHTRANSFORM b2a = cmsCreateTransform(lab, TYPE_Lab_DBL, prof, TYPE_RGB_DBL, INTENT_RELATIVE_COLORIMETRIC, 0);
  std::vector<std::array<double, 3>> table(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const cmsCIELab in{targets[i].l, targets[i].a, targets[i].b};
    cmsDoTransform(b2a, &in, table[i].data(), 1);
  }
  cmsDeleteTransform(b2a);
  cmsCloseProfile(lab);
  cmsCloseProfile(prof);
  const std::vector<device::Lab> via_table = inv->colour_of(table);
  double worst = 0, table_mean = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    worst = std::max(worst, device::delta_e_2000(targets[i], got[i]));
    table_mean += device::delta_e_2000(targets[i], via_table[i]) / static_cast<double>(targets.size());
  }
  EXPECT_LT(worst, 0.05);
  EXPECT_GT(table_mean, 1.0) << "the B2A table is crude on purpose";
}

TEST(RgbProfileInverse, ClipsOutOfGamutColoursToTheClosestItCanMake) {
  auto inv = RgbProfileInverse::open(write_profile("tp_inverse_clip"));
  ASSERT_TRUE(inv) << inv.error().message;
  // Far more chroma than the model's red: the answer stays in the box and is nearer than red.
  const device::Lab want{50, 120, 60};
  const auto rgb = inv->device_for({want});
  for (double c : rgb[0]) {
    EXPECT_GE(c, 0.0);
    EXPECT_LE(c, 1.0);
  }
  const device::Lab got = inv->colour_of(rgb).front();
  const device::Lab red = inv->colour_of({{1.0, 0.0, 0.0}}).front();
  auto d76 = [](const device::Lab& a, const device::Lab& b) { return std::hypot(a.l - b.l, a.a - b.a, a.b - b.b); };
  EXPECT_LE(d76(got, want), d76(red, want) + 0.05);
}

TEST(RgbProfileInverse, RefusesWhatIsNotAnRgbOutputProfile) {
  auto missing = RgbProfileInverse::open("/nonexistent/cal.icc");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("/nonexistent/cal.icc"), std::string::npos);
  const auto path = std::filesystem::temp_directory_path() / "tp_profile_inverse_srgb.icc";
  cmsHPROFILE srgb = cmsCreate_sRGBProfile();
  cmsSaveProfileToFile(srgb, path.c_str());
  cmsCloseProfile(srgb);
  auto display = RgbProfileInverse::open(path);
  ASSERT_FALSE(display);
  EXPECT_NE(display.error().message.find("must be an RGB output profile"), std::string::npos);
}

}  // namespace
}  // namespace tp::rip
