// tests/scenarios/jobs/pattern_jobs_test.cpp: outside patterns through `printctl run`: a FreeSewing
// pattern without stitches is refused on a body, sewn with suggested stitches or a stitches file,
// and printed flat without a body; every stitch is reported with its source and the fit checks.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A job package in `dir` holding FreeSewing's teagan (size 34) and the given garment fields.
fs::path teagan_job(const fs::path& dir, const json& garment_extra, bool body) {
  const fs::path job = dir / "job";
  fs::create_directories(job);
  fs::copy_file(shared_data_dir() / "freesewing/teagan-cisFemaleAdult34.svg", job / "teagan.svg");
  json garment = {{"pattern", "teagan.svg"}, {"mesh_edge", "25 mm"}};
  if (body) garment["body"] = {{"dress_form", json::object()}};
  for (auto it = garment_extra.begin(); it != garment_extra.end(); ++it) garment[it.key()] = it.value();
  json j = {{"format", "tp-job/1"},
            {"name", "teagan"},
            {"garment", garment},
            {"design", {{"layers", json::array({{{"type", body ? "cylindrical" : "planar"},
                                                 {"procedural", {{"kind", "stripes"}, {"count", 4}, {"size_px", 256}}}}})}}},
            {"marker", {{"fabric_width", "1.6 m"}, {"time_limit_s", 1}}},
            {"print", {{"dpi", 50}, {"preview_dpi", 20}}}};
  if (!body) {
    auto& l = j["design"]["layers"][0];
    l["centre"] = {"40 cm", "30 cm", 0};
    l["width"] = "20 cm";
    l["repeat"] = true;
  }
  std::ofstream(job / "job.json") << j.dump(2);
  return job;
}

CommandResult run_job(const fs::path& job, const fs::path& out) {
  return run_command({(bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string(), "--printer", "none"});
}

TEST(PatternJobs, ThreeDJobWithoutStitchesIsRefusedWithTheReason) {
  const fs::path dir = scratch_dir("pattern-no-stitches");
  auto r = run_job(teagan_job(dir, json::object(), true), dir / "out");
  EXPECT_NE(r.exit_code, 0);
  const json rep = read_json(dir / "out/report.json");
  EXPECT_EQ(rep["state"], "failed");
  const std::string err = rep.value("error", "");
  EXPECT_NE(err.find("no stitches to sew it on the body"), std::string::npos) << err;
  EXPECT_NE(err.find("\"suggest\""), std::string::npos) << err;
  EXPECT_FALSE(rep.contains("garment"));
}

TEST(PatternJobs, ValidateRefusesAThreeDJobWithoutStitchesAndPassesAFlatOrSuggestedOne) {
  const fs::path dir = scratch_dir("pattern-validate");
  auto validate = [](const fs::path& job) {
    return run_command({(bin_dir() / "printctl").string(), "validate", job.string()});
  };
  auto refused = validate(teagan_job(dir / "body", json::object(), true));
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.output.find("/garment: pattern 'teagan': no stitches to sew it on the body"), std::string::npos)
      << refused.output;
  auto flat = validate(teagan_job(dir / "flat", json::object(), false));
  EXPECT_EQ(flat.exit_code, 0) << flat.output;
  auto suggest = validate(teagan_job(dir / "suggest", {{"stitches", "suggest"}}, true));
  EXPECT_EQ(suggest.exit_code, 0) << suggest.output;
}

TEST(PatternJobs, FlatJobWithoutStitchesStillPrints) {
  const fs::path dir = scratch_dir("pattern-flat");
  auto r = run_job(teagan_job(dir, json::object(), false), dir / "out");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json rep = read_json(dir / "out/report.json");
  EXPECT_EQ(rep["state"], "done");
  EXPECT_EQ(rep["garment"]["mode"], "flat");
  EXPECT_TRUE(rep["garment"]["stitches"].empty());
}

TEST(PatternJobs, SuggestedStitchesAreSewnAndReportedWithScoreAndReason) {
  const fs::path dir = scratch_dir("pattern-suggest");
  // The limit on self-intersections is the job's to loosen (teagan's sleeves fold at the armpit).
  // ARAP named: at this test's 25 mm mesh XPBD ("auto" for a FreeSewing pattern) sews on a 50 mm
  // coarse level that leaves the sleeves' underarm seams 2.3 mm open (docs/garments.md).
  auto r = run_job(
      teagan_job(dir, {{"stitches", "suggest"}, {"sewing", "arap"}, {"checks", {{"self_intersections", 0.05}}}}, true),
      dir / "out");
  const json rep = read_json(dir / "out/report.json");
  ASSERT_TRUE(rep.contains("garment")) << rep.dump(1);
  const json& g = rep["garment"];
  ASSERT_GE(g["stitches"].size(), 8u);
  for (const json& s : g["stitches"]) {
    EXPECT_EQ(s["source"], "suggested");
    EXPECT_GE(s["score"].get<double>(), 0.7);
    EXPECT_FALSE(s["reason"].get<std::string>().empty());
    EXPECT_TRUE(s.contains("gap_max_mm"));
  }
  ASSERT_TRUE(g.contains("checks"));
  EXPECT_LE(g["checks"]["stitch_gap_max_mm"].get<double>(), 2.0) << g["checks"].dump(1);
  EXPECT_EQ(g["checks"]["inside_body"], 0);
  EXPECT_EQ(g["checks"]["pass"], true) << g["checks"].dump(1);
  EXPECT_EQ(rep["state"], "done") << rep.value("error", "");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(PatternJobs, StitchesFileFromPatternSuggestIsUsedAndTooTightLimitsFailNamingThePreview) {
  const fs::path dir = scratch_dir("pattern-stitches-file");
  const fs::path job = teagan_job(dir, {{"stitches_file", "stitches.json"}, {"checks", {{"stitch_gap", "0.001 mm"}}}}, true);
  auto s = run_command({(bin_dir() / "printctl").string(), "pattern", "suggest", (job / "teagan.svg").string(), "--out",
                        (job / "stitches.json").string()});
  ASSERT_EQ(s.exit_code, 0) << s.output;
  EXPECT_EQ(read_json(job / "stitches.json")["format"], "tp-stitches");
  auto r = run_job(job, dir / "out");
  EXPECT_NE(r.exit_code, 0);
  const json rep = read_json(dir / "out/report.json");
  EXPECT_EQ(rep["state"], "failed");
  ASSERT_TRUE(rep["garment"].contains("stitches"));
  for (const json& st : rep["garment"]["stitches"]) EXPECT_EQ(st["source"], "job");
  const std::string err = rep.value("error", "");
  EXPECT_NE(err.find("garment checks failed: stitch gap"), std::string::npos) << err;
  EXPECT_NE(err.find("(look at garment-"), std::string::npos) << err;
  EXPECT_EQ(rep["garment"]["checks"]["pass"], false);
  // The pieces start outside the body (pushed out of it), and the report says how many were in.
  const json& start = rep["garment"]["start"];
  EXPECT_EQ(start["inside_body_pushed"], 0) << start.dump();
  EXPECT_GE(start["inside_body_placed"].get<int>(), 0) << start.dump();
  // "auto" sews a pattern whose pieces come without a placement with XPBD.
  EXPECT_EQ(rep["sewing"]["solver"], "xpbd") << rep["sewing"].dump();
  EXPECT_EQ(rep["sewing"]["solver_asked"], "auto") << rep["sewing"].dump();
  EXPECT_EQ(rep["sewing"]["levels"], 1) << rep["sewing"].dump();
  EXPECT_EQ(rep["sewing"]["coarse_discarded"], 0) << rep["sewing"].dump();
}

}  // namespace
}  // namespace tp::test
