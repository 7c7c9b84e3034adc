// tests/host/job/garment_material_test.cpp: garment.material, drape, correspondence, sewing and checks in job.json.
#include <gtest/gtest.h>

#include <fstream>

#include "host/job/manifest.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

class GarmentMaterialTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = tp::test::scratch_dir("garment_material");
    std::ofstream(dir_ / "pattern.json") << "{}";
  }
  Result<Job> load(const std::string& garment_fields) {
    std::ofstream(dir_ / "job.json") << R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "pattern.json")"
                                     << garment_fields << R"(}, "marker": {"fabric_width": "1.5 m"}})";
    auto pkg = JobPackage::open(dir_, dir_ / "unused");
    if (!pkg) return std::unexpected(pkg.error());
    return load_job(*pkg);
  }
  std::filesystem::path dir_;
};

TEST_F(GarmentMaterialTest, DefaultsArePoplinDrapedSewnCorrespondence) {
  auto job = load("");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.material.preset, "cotton-poplin");
  EXPECT_TRUE(job->garment.drape);
  EXPECT_EQ(job->garment.correspondence, "sewn");
}

TEST_F(GarmentMaterialTest, PresetNameOrObjectWithOverrides) {
  auto job = load(R"(, "material": "denim")");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.material.preset, "denim");
  job = load(R"(, "material": {"preset": "jersey", "density_g_m2": 210, "friction": 0.3}, "correspondence": "draped")");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.material.preset, "jersey");
  EXPECT_EQ(job->garment.material.density_g_m2, 210);
  EXPECT_EQ(job->garment.material.friction, 0.3);
  EXPECT_FALSE(job->garment.material.stretch_limit);
  EXPECT_EQ(job->garment.correspondence, "draped");
}

TEST_F(GarmentMaterialTest, BadValuesNameTheField) {
  auto job = load(R"(, "material": "tweed")");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/garment/material"), std::string::npos) << job.error().message;
  EXPECT_NE(job.error().message.find("silk-satin"), std::string::npos) << job.error().message;
  job = load(R"(, "material": {"friction": 5})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/garment/material/friction"), std::string::npos) << job.error().message;
  job = load(R"(, "drape": false, "correspondence": "draped")");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/garment/correspondence"), std::string::npos) << job.error().message;
}

TEST_F(GarmentMaterialTest, SewingSolverIsAutoByDefaultOrArapOrXpbd) {
  auto job = load("");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.sewing, "auto");
  job = load(R"(, "sewing": "arap")");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.sewing, "arap");
  job = load(R"(, "sewing": "xpbd")");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.sewing, "xpbd");
  job = load(R"(, "sewing": "springs")");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/garment/sewing"), std::string::npos) << job.error().message;
}

TEST_F(GarmentMaterialTest, FitCheckLimitsAreReadAndBadOnesNamed) {
  auto job = load("");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.checks.max_body_crossings, 1);  // reported, not limited
  job = load(R"(, "checks": {"body_crossings": 0, "inside_body": 0.01})");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->garment.checks.max_body_crossings, 0);
  EXPECT_EQ(job->garment.checks.max_inside_body, 0.01);
  job = load(R"(, "checks": {"body_crossings": 2})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/garment/checks/body_crossings"), std::string::npos) << job.error().message;
  job = load(R"(, "checks": {"body_crossing": 0})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/garment/checks/body_crossing: unknown field"), std::string::npos)
      << job.error().message;
}

}  // namespace
}  // namespace tp::host
