// tests/host/pipeline/plan_storage_test.cpp: a job's plan is made once: a resume or a reprint
// loads the stored garment and marker, a print-only change keeps them, a pieces change re-nests
// but keeps the garment, and a swath that differs from the stored plan is never sent.
#include <gtest/gtest.h>

#include "tests/host/pipeline/plan_job.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(PlanStorage, AResumeLoadsThePlanAndReRunsNoPlanStage) {
  const fs::path dir = scratch_dir("plan_resume");
  const host::Job job = write_plan_job(dir / "job", plan_job_manifest());
  const json first = run_plan_job(job, dir / "out1", dir / "plan");
  ASSERT_EQ(first["state"], "done") << first.dump(1);
  for (const char* stage : {"pattern", "mesh", "garment", "design", "marker", "print", "outputs"})
    EXPECT_EQ(stage_state(first, stage), "done") << stage;
  EXPECT_EQ(first["plan"]["steps"]["garment"], "made");
  EXPECT_EQ(first["plan"]["steps"]["marker"], "made");
  EXPECT_EQ(first["plan"]["steps"]["swaths"], "made");
  for (const char* f : {"plan.json", "garment.plan", "pieces.json", "marker.json", "swaths.json"})
    EXPECT_TRUE(fs::is_regular_file(dir / "plan" / f)) << f;
  const std::string marker = file_bytes(dir / "plan" / "marker.json");
  const std::string garment = file_bytes(dir / "plan" / "garment.plan");

  // Nothing changed; resume after swath 2: nothing is meshed, sewn or nested again.
  const json resumed = run_plan_job(job, dir / "out2", dir / "plan", 2);
  ASSERT_EQ(resumed["state"], "done") << resumed.dump(1);
  EXPECT_EQ(stage_state(resumed, "mesh"), "reused");
  EXPECT_EQ(stage_state(resumed, "garment"), "reused");
  EXPECT_EQ(stage_state(resumed, "marker"), "reused");
  EXPECT_EQ(resumed["marker"]["source"], "plan");
  EXPECT_EQ(resumed.contains("sewing"), false) << "the garment was sewn again";
  const int swaths = first["rip"]["swaths"];
  ASSERT_GT(swaths, 3);
  EXPECT_EQ(resumed["plan"]["steps"]["swaths"],
            "verified " + std::to_string(swaths - 3) + " of " + std::to_string(swaths));
  EXPECT_EQ(file_bytes(dir / "plan" / "marker.json"), marker);
  EXPECT_EQ(file_bytes(dir / "plan" / "garment.plan"), garment);
  // What the resume writes comes from the same layout as the first run's.
  for (const char* f : {"cut.dxf", "cut.svg", "marker.png", "garment.obj"})
    EXPECT_EQ(file_bytes(dir / "out2" / f), file_bytes(dir / "out1" / f)) << f;
  EXPECT_EQ(resumed["marker"]["length_mm"], first["marker"]["length_mm"]);
}

TEST(PlanStorage, APrintOnlyChangeKeepsTheGarmentAndTheMarker) {
  const fs::path dir = scratch_dir("plan_print_change");
  const json first = run_plan_job(write_plan_job(dir / "job1", plan_job_manifest(50)), dir / "out1", dir / "plan");
  ASSERT_EQ(first["state"], "done");
  const std::string marker = file_bytes(dir / "plan" / "marker.json");
  const std::string swaths = file_bytes(dir / "plan" / "swaths.json");

  const json reprint = run_plan_job(write_plan_job(dir / "job2", plan_job_manifest(60)), dir / "out2", dir / "plan");
  ASSERT_EQ(reprint["state"], "done") << reprint.dump(1);
  EXPECT_EQ(stage_state(reprint, "garment"), "reused");
  EXPECT_EQ(stage_state(reprint, "marker"), "reused");
  EXPECT_EQ(file_bytes(dir / "plan" / "marker.json"), marker);
  // The swaths follow the new resolution: a new swath plan.
  EXPECT_EQ(reprint["plan"]["steps"]["swaths"], "made");
  EXPECT_NE(file_bytes(dir / "plan" / "swaths.json"), swaths);
  EXPECT_EQ(file_bytes(dir / "out2" / "cut.dxf"), file_bytes(dir / "out1" / "cut.dxf"));
}

TEST(PlanStorage, AWiderSeamAllowanceReNestsButKeepsTheGarment) {
  const fs::path dir = scratch_dir("plan_pieces_change");
  const json first = run_plan_job(write_plan_job(dir / "job1", plan_job_manifest(50, "1 cm")), dir / "out1", dir / "plan");
  ASSERT_EQ(first["state"], "done");
  const json second = run_plan_job(write_plan_job(dir / "job2", plan_job_manifest(50, "1.5 cm")), dir / "out2", dir / "plan");
  ASSERT_EQ(second["state"], "done") << second.dump(1);
  EXPECT_EQ(stage_state(second, "garment"), "reused");
  EXPECT_EQ(stage_state(second, "marker"), "done");
  EXPECT_EQ(second["plan"]["steps"]["marker"], "made");
  EXPECT_NE(file_bytes(dir / "out2" / "cut.dxf"), file_bytes(dir / "out1" / "cut.dxf"));
}

TEST(PlanStorage, ASwathThatDiffersFromThePlanIsNeverSent) {
  const fs::path dir = scratch_dir("plan_swath_mismatch");
  const host::Job job = write_plan_job(dir / "job", plan_job_manifest());
  ASSERT_EQ(run_plan_job(job, dir / "out1", dir / "plan")["state"], "done");
  // Stand in for a layout that changed under the printed fabric: swath 3's digest is altered.
  json plan = json::parse(file_bytes(dir / "plan" / "swaths.json"));
  ASSERT_GT(plan["swaths"].size(), 3u);
  plan["swaths"][3]["digest"] = "00000000000000000000000000000000";
  std::ofstream(dir / "plan" / "swaths.json") << plan.dump(1);

  host::RunOptions o;
  o.out_dir = dir / "out2";
  o.printer_override = host::PrinterChoice::kNone;
  o.plan_dir = dir / "plan";
  o.resume_after_swath = 1;
  o.job_id = 1;
  auto st = host::run_job(job, o, {});
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find("swath 3 differs from the job's stored plan"), std::string::npos)
      << st.error().message;
  const json rep = json::parse(file_bytes(dir / "out2" / "report.json"));
  EXPECT_EQ(rep["state"], "failed");
  EXPECT_EQ(stage_state(rep, "print"), "failed");
}

TEST(PlanStorage, ACorruptStoredGarmentFailsNamingTheFile) {
  const fs::path dir = scratch_dir("plan_corrupt");
  const host::Job job = write_plan_job(dir / "job", plan_job_manifest());
  ASSERT_EQ(run_plan_job(job, dir / "out1", dir / "plan")["state"], "done");
  std::string text = file_bytes(dir / "plan" / "garment.plan");
  text.replace(text.find("vertices "), 9, "vertixes ");
  std::ofstream(dir / "plan" / "garment.plan", std::ios::binary) << text;

  host::RunOptions o;
  o.out_dir = dir / "out2";
  o.printer_override = host::PrinterChoice::kNone;
  o.plan_dir = dir / "plan";
  auto st = host::run_job(job, o, {});
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find("garment.plan: line 3"), std::string::npos) << st.error().message;
  EXPECT_EQ(stage_state(json::parse(file_bytes(dir / "out2" / "report.json")), "garment"), "failed");
}

}  // namespace
}  // namespace tp::test
