// tests/simulator/fabric/spectro_measure_test.cpp: the simulated spectrophotometer reads the
// patch colour under its aperture, repeats with a seed, and refuses charts it cannot read.
#include "simulator/fabric/spectro_measure.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <fstream>

#include "device/model/cgats.h"
#include "device/colour/colorimetry.h"
#include "simulator/fabric/fabric_preset.h"
#include "tests/support/paths.h"

namespace tp::sim {
namespace {

// A 40 x 20 px Lab image at 25.4 dpi (1 px = 1 mm): left half one colour, right half another.
std::filesystem::path write_fabric(const std::filesystem::path& dir) {
  const auto path = dir / "fabric-lab.tif";
  OIIO::ImageSpec s(40, 20, 3, OIIO::TypeDesc::FLOAT);
  s.attribute("XResolution", 25.4f);
  s.attribute("YResolution", 25.4f);
  s.attribute("ResolutionUnit", "inch");
  std::vector<float> px(40 * 20 * 3);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      float* p = &px[(static_cast<std::size_t>(y) * 40 + x) * 3];
      p[0] = x < 20 ? 50.f : 80.f;
      p[1] = x < 20 ? 20.f : -10.f;
      p[2] = x < 20 ? -30.f : 40.f;
    }
  auto out = OIIO::ImageOutput::create(path.string());
  EXPECT_TRUE(out && out->open(path.string(), s));
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
  EXPECT_TRUE(out->close());
  return path;
}

std::filesystem::path write_chart(const std::filesystem::path& dir, double second_x_mm) {
  const auto path = dir / "chart.ti2";
  std::ofstream(path) << "CTI2\nCOLOR_REP \"CMYK\"\nBEGIN_DATA_FORMAT\nSAMPLE_ID CMYK_C CMYK_M CMYK_Y CMYK_K TP_X_MM TP_Y_MM\n"
                         "END_DATA_FORMAT\nNUMBER_OF_SETS 2\nBEGIN_DATA\n1 100 0 0 0 10 10\n2 0 0 100 0 "
                      << second_x_mm << " 10\nEND_DATA\n";
  return path;
}

Lab lab_of(const std::vector<std::string>& row) {
  return xyz_to_lab({std::stod(row[5]) / 100, std::stod(row[6]) / 100, std::stod(row[7]) / 100});
}

TEST(SpectroMeasure, ReadsEachPatchUnderTheAperture) {
  const auto dir = test::scratch_dir("spectro");
  MeasureOptions o{write_chart(dir, 30), write_fabric(dir), dir / "m.ti3", 6, 0, 1};
  auto r = measure_chart(o);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->patches, 2u);
  EXPECT_GE(r->min_samples, 20);
  auto t = device::load_cgats(o.out_ti3);
  ASSERT_TRUE(t) << t.error().message;
  const auto& m = t->front();
  EXPECT_EQ(m.type, "CTI3");
  EXPECT_EQ(m.keyword("COLOR_REP"), "CMYK_XYZ");
  ASSERT_EQ(m.fields, (std::vector<std::string>{"SAMPLE_ID", "CMYK_C", "CMYK_M", "CMYK_Y", "CMYK_K", "XYZ_X", "XYZ_Y", "XYZ_Z"}));
  ASSERT_EQ(m.rows.size(), 2u);
  EXPECT_EQ(m.rows[0][1], "100");
  EXPECT_LT(delta_e_2000(lab_of(m.rows[0]), {50, 20, -30}), 0.01);
  EXPECT_LT(delta_e_2000(lab_of(m.rows[1]), {80, -10, 40}), 0.01);
}

TEST(SpectroMeasure, NoiseIsSeededAndOfTheAskedSize) {
  const auto dir = test::scratch_dir("spectro-noise");
  MeasureOptions o{write_chart(dir, 30), write_fabric(dir), dir / "a.ti3", 6, 0.5, 7};
  ASSERT_TRUE(measure_chart(o));
  o.out_ti3 = dir / "b.ti3";
  ASSERT_TRUE(measure_chart(o));
  auto a = device::load_cgats(dir / "a.ti3"), b = device::load_cgats(dir / "b.ti3");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->front().rows, b->front().rows) << "same seed, same reading";
  const double de = delta_e_2000(lab_of(a->front().rows[0]), {50, 20, -30});
  EXPECT_GT(de, 0.0);
  EXPECT_LT(de, 3.0);
}

TEST(SpectroMeasure, RefusesPatchesOffTheFabricAndChartsWithoutLayout) {
  const auto dir = test::scratch_dir("spectro-bad");
  MeasureOptions o{write_chart(dir, 39), write_fabric(dir), dir / "m.ti3", 6, 0, 1};
  auto r = measure_chart(o);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("patch 2"), std::string::npos) << r.error().message;
  std::ofstream(dir / "nolayout.ti1") << "CTI1\nBEGIN_DATA_FORMAT\nSAMPLE_ID CMYK_C\nEND_DATA_FORMAT\nBEGIN_DATA\n1 0\nEND_DATA\n";
  o.chart = dir / "nolayout.ti1";
  r = measure_chart(o);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("TP_X_MM"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace tp::sim
