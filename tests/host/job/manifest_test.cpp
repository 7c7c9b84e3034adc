// tests/host/job/manifest_test.cpp: job.json validation names the file and the JSON pointer.
#include "host/job/manifest.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

class ManifestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = tp::test::scratch_dir("manifest");
    std::ofstream(dir_ / "pattern.json") << "{}";
    std::ofstream(dir_ / "motif.png") << "png";
  }
  // Writes job.json and loads the package.
  Result<Job> load(const std::string& text) {
    std::ofstream(dir_ / "job.json") << text;
    auto pkg = JobPackage::open(dir_, dir_ / "unused");
    if (!pkg) return std::unexpected(pkg.error());
    return load_job(*pkg);
  }
  fs::path dir_;
};

const char* kMinimal = R"({"format": "tp-job/1", "name": "t1",
  "garment": {"pattern": "pattern.json"}, "marker": {"fabric_width": "1.5 m"}})";

TEST_F(ManifestTest, MinimalJobLoadsWithDefaultsAndUnits) {
  auto job = load(kMinimal);
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->name, "t1");
  EXPECT_DOUBLE_EQ(job->marker.fabric_width_mm, 1500.0);
  ASSERT_TRUE(job->garment.pattern);
  EXPECT_EQ(job->garment.pattern->filename(), "pattern.json");
  EXPECT_EQ(job->print.dpi, 600);
  EXPECT_DOUBLE_EQ(job->finishing.seam_allowance_mm, 10.0);
}

TEST_F(ManifestTest, MissingRequiredFieldNamesPointer) {
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "pattern.json"}})");
  ASSERT_FALSE(job);
  EXPECT_EQ(job.error().code, ErrorCode::kValidation);
  EXPECT_NE(job.error().message.find("job.json: /marker: required field is missing"), std::string::npos)
      << job.error().message;
}

TEST_F(ManifestTest, WrongTypeNamesPointerAndType) {
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "pattern.json"},
                      "marker": {"fabric_width": 1500}, "print": {"dpi": "600"}})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("job.json: /print/dpi: expected an integer, got a string"), std::string::npos)
      << job.error().message;
}

TEST_F(ManifestTest, UnknownUnitIsRefused) {
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "pattern.json"},
                      "marker": {"fabric_width": 1500}, "finishing": {"seam_allowance": "3 px"}})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/finishing/seam_allowance: unknown unit 'px'"), std::string::npos)
      << job.error().message;
}

TEST_F(ManifestTest, MissingAssetIsNamed) {
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "nope.json"},
                      "marker": {"fabric_width": 1500}})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/garment/pattern: asset \"nope.json\" is missing"), std::string::npos)
      << job.error().message;
}

TEST_F(ManifestTest, UnsafePathsAreRefused) {
  for (const char* bad : {"/etc/passwd", "../pattern.json", "a/../../x"}) {
    auto job = load(std::string(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": ")") + bad +
                    R"("}, "marker": {"fabric_width": 1500}})");
    ASSERT_FALSE(job) << bad;
    EXPECT_EQ(job.error().code, ErrorCode::kUnsafePath) << bad << ": " << job.error().message;
    EXPECT_NE(job.error().message.find("/garment/pattern"), std::string::npos) << job.error().message;
  }
}

TEST_F(ManifestTest, SymlinkOutOfPackageIsRefused) {
  fs::path outside = tp::test::scratch_dir("manifest-outside") / "secret.json";
  std::ofstream(outside) << "{}";
  fs::create_symlink(outside, dir_ / "link.json");
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "link.json"},
                      "marker": {"fabric_width": 1500}})");
  ASSERT_FALSE(job);
  EXPECT_EQ(job.error().code, ErrorCode::kUnsafePath);
  EXPECT_NE(job.error().message.find("leaves the package"), std::string::npos) << job.error().message;
}

TEST_F(ManifestTest, UnknownFieldAndBadChoiceAreBothReported) {
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "pattern.json"},
                      "marker": {"fabric_width": 1500, "rotation": "free"},
                      "print": {"screen": "amplitude"}})");
  ASSERT_FALSE(job);
  const std::string& m = job.error().message;
  EXPECT_NE(m.find("/marker/rotation: unknown field"), std::string::npos) << m;
  EXPECT_NE(m.find("/print/screen: unknown value \"amplitude\""), std::string::npos) << m;
}

TEST_F(ManifestTest, DesignLayersAreRead) {
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "pattern.json"},
      "marker": {"fabric_width": 1500},
      "design": {"layers": [
        {"type": "planar", "image": "motif.png", "centre": [0, "12 cm", 0], "width": "20 cm"},
        {"type": "cylindrical", "procedural": {"kind": "marbling", "seed": 4}, "tile_width": 300},
        {"type": "stroke", "points": [[0, 0, 0], [10, 0, 0]], "radius": "4 mm", "colour": [200, 0, 0, 255]}]}})");
  ASSERT_TRUE(job) << job.error().message;
  ASSERT_EQ(job->design.size(), 3u);
  EXPECT_DOUBLE_EQ(job->design[0].centre_mm[1], 120.0);
  EXPECT_DOUBLE_EQ(job->design[0].width_mm, 200.0);
  EXPECT_EQ(job->design[1].procedural, "marbling");
  EXPECT_EQ(job->design[1].procedural_seed, 4);
  ASSERT_EQ(job->design[2].points_mm.size(), 2u);
  EXPECT_EQ(job->design[2].colour_rgba[0], 200);
}

TEST_F(ManifestTest, BrokenJsonIsReported) {
  auto job = load(R"({"format": "tp-job/1", )");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("job.json: not valid JSON"), std::string::npos);
  // A number too large for a double is refused, not thrown past the parser (found by the fuzzer).
  auto huge = load(R"({"format": "tp-job/1", "name": 4444444444444444444444e444444})");
  ASSERT_FALSE(huge);
  EXPECT_NE(huge.error().message.find("job.json: not valid JSON"), std::string::npos) << huge.error().message;
  EXPECT_NE(huge.error().message.find("number overflow"), std::string::npos) << huge.error().message;
}

TEST_F(ManifestTest, BadStrokePointNamesElement) {
  auto job = load(R"({"format": "tp-job/1", "name": "t1", "garment": {"pattern": "pattern.json"},
      "marker": {"fabric_width": 1500},
      "design": {"layers": [{"type": "stroke", "points": [[0, 0, 0], [1, "x", 0]], "radius": 3}]}})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/design/layers/0/points/1/1"), std::string::npos) << job.error().message;
}

}  // namespace
}  // namespace tp::host
