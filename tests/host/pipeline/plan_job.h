// tests/host/pipeline/plan_job.h: a small 3D job (the eight-gore skirt on its dress form, a
// coarse mesh, a reproducible marker) written into a test folder, and helpers to run and read it.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "host/job/manifest.h"
#include "host/job/package.h"
#include "host/pipeline/run_job.h"

namespace tp::test {

/// job.json of the test job; `print_dpi` and `seam_allowance` vary the print and the pieces.
inline nlohmann::json plan_job_manifest(int print_dpi = 50, const std::string& seam_allowance = "1 cm") {
  nlohmann::json j = nlohmann::json::parse(R"({
    "format": "tp-job/1",
    "name": "plan-skirt",
    "garment": {"sample": "skirt8", "size": "M", "mesh_edge": "40 mm"},
    "design": {"layers": [
      {"type": "cylindrical", "name": "stripes",
       "procedural": {"kind": "stripes", "count": 6, "vertical": true, "size_px": 256}, "tile_width": "30 cm"}]},
    "finishing": {"hem_allowance": "2 cm"},
    "marker": {"fabric_width": "1.4 m", "gap": "4 mm", "budget": {"iterations": 150}, "seed": 3},
    "print": {"printer": "sim", "passes": 4, "preview_dpi": 20}
  })");
  j["print"]["dpi"] = print_dpi;
  j["finishing"]["seam_allowance"] = seam_allowance;
  return j;
}

/// Writes `manifest` as `<dir>/job.json` and loads it as a validated job.
inline host::Job write_plan_job(const std::filesystem::path& dir, const nlohmann::json& manifest) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "job.json") << manifest.dump(2);
  auto pkg = host::JobPackage::open(dir, dir / "unused");
  EXPECT_TRUE(pkg) << (pkg ? "" : pkg.error().message);
  auto job = host::load_job(*pkg);
  EXPECT_TRUE(job) << (job ? "" : job.error().message);
  return *job;
}

/// Runs `job` without a printer into `out`, with the plan in `plan_dir` (none when empty).
inline nlohmann::json run_plan_job(const host::Job& job, const std::filesystem::path& out,
                                   const std::filesystem::path& plan_dir, std::int64_t resume_after = -1) {
  host::RunOptions o;
  o.out_dir = out;
  o.printer_override = host::PrinterChoice::kNone;
  o.plan_dir = plan_dir;
  o.resume_after_swath = resume_after;
  o.job_id = 1;
  auto st = host::run_job(job, o, {});
  EXPECT_TRUE(st) << (st ? "" : st.error().message);
  std::ifstream in(out / "report.json");
  return nlohmann::json::parse(in);
}

/// The state a report gives `stage` ("done", "reused", ...).
inline std::string stage_state(const nlohmann::json& report, const std::string& stage) {
  for (const auto& s : report["stages"])
    if (s["stage"] == stage) return s["state"];
  return "absent";
}

/// A file's bytes ("" when it cannot be read).
inline std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace tp::test
