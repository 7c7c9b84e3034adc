// tests/host/pipeline/job_stitch_check_test.cpp: a job to be sewn on a body whose pattern has no stitches is refused at
// intake.
#include "host/pipeline/job_stitch_check.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "host/daemon/intake.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A job folder with FreeSewing's teagan (no stitches of its own) and the given garment fields.
fs::path teagan_job(const std::string& name, const json& garment_extra, bool body) {
  const fs::path job = test::scratch_dir(name) / "job";
  fs::create_directories(job);
  fs::copy_file(test::shared_data_dir() / "freesewing/teagan-cisFemaleAdult34.svg", job / "teagan.svg",
                fs::copy_options::overwrite_existing);
  json garment = {{"pattern", "teagan.svg"}};
  if (body) garment["body"] = {{"dress_form", json::object()}};
  for (auto it = garment_extra.begin(); it != garment_extra.end(); ++it) garment[it.key()] = it.value();
  json layer = {{"type", "planar"},
                {"procedural", {{"kind", "stripes"}, {"count", 4}, {"size_px", 256}}},
                {"centre", {"40 cm", "30 cm", 0}},
                {"width", "20 cm"}};
  json j = {{"format", "tp-job/1"},
            {"name", "teagan"},
            {"garment", garment},
            {"design", {{"layers", json::array({layer})}}},
            {"marker", {{"fabric_width", "1.6 m"}}}};
  std::ofstream(job / "job.json") << j.dump(2);
  return job;
}

Result<CheckedPackage> intake(const fs::path& job) {
  return check_package(job, job.parent_path() / "scratch", {}, check_job_stitches);
}

TEST(JobStitchCheck, BodyWithoutStitchesIsRefusedAtIntakeWithTheReason) {
  auto r = intake(teagan_job("stitch-check-none", json::object(), true));
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kValidation);
  const std::string& m = r.error().message;
  EXPECT_NE(m.find("job.json: /garment: pattern 'teagan': no stitches to sew it on the body"), std::string::npos) << m;
  EXPECT_NE(m.find("set /garment/stitches to \"suggest\""), std::string::npos) << m;
  // Without the check (the fuzzers' and tests' intake) the same package is taken.
  EXPECT_TRUE(check_package(teagan_job("stitch-check-none", json::object(), true),
                            test::scratch_dir("stitch-check-none") / "scratch"));
}

TEST(JobStitchCheck, SuggestionsScoringUnderTheMinimumCountAsNone) {
  auto r = intake(teagan_job("stitch-check-score", {{"stitches", "suggest"}, {"suggest_min_score", 0.99}}, true));
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("no suggestion scored 0.99 or more"), std::string::npos) << r.error().message;
}

TEST(JobStitchCheck, SuggestedStitchesOrNoBodyPass) {
  EXPECT_TRUE(intake(teagan_job("stitch-check-suggest", {{"stitches", "suggest"}}, true)));
  auto flat = intake(teagan_job("stitch-check-flat", json::object(), false));
  EXPECT_TRUE(flat) << flat.error().message;
}

TEST(JobStitchCheck, AnUnreadablePatternIsRefusedNamingTheField) {
  const fs::path job = teagan_job("stitch-check-broken", json::object(), true);
  std::ofstream(job / "teagan.svg") << "<svg><path d='M 0 0 L'/>";
  auto r = intake(job);
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("/garment/pattern"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace tp::host
