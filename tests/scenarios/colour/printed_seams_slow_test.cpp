// tests/scenarios/colour/printed_seams_slow_test.cpp: the printed-seam figures see a piece printed
// 3 mm off or turned 1 degree from where the marker and cut file place it (printctl run
// --debug-misplace), where the contone figures, taken before printing, cannot; and the report's
// gamut section with its soft proof files.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/scenarios/jobs/report_schema.h"
#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Runs examples/top-strokes; `drape` false: a copy of it whose garment is not draped (the drape
// gives previews only, none of the figures these tests read).
json run_top(const std::string& name, const std::vector<std::string>& extra, bool drape = false) {
  const fs::path dir = scratch_dir("printed-seams-" + name), out = dir / "out";
  fs::path job = source_dir() / "examples/top-strokes";
  if (!drape) {
    const fs::path copy = dir / "job";
    fs::create_directories(copy.parent_path());
    fs::copy(job, copy, fs::copy_options::recursive);
    json j = read_json(copy / "job.json");
    j["garment"]["drape"] = false;
    std::ofstream(copy / "job.json") << j.dump(2);
    job = copy;
  }
  std::vector<std::string> cmd{(bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string()};
  cmd.insert(cmd.end(), extra.begin(), extra.end());
  auto r = run_command(cmd);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(out / "report.json");
  json rep = json::parse(in);
  rep["_out"] = out.string();
  return rep;
}

// The worst seam mean of the printed figures among the seams that join `piece` to another piece.
double worst_seam_with(const json& rep, const std::string& piece) {
  double worst = 0;
  for (const json& s : rep["seams_printed"]["list"])
    if ((s["piece_a"] == piece) != (s["piece_b"] == piece)) worst = std::max(worst, s["de00_mean"].get<double>());
  return worst;
}

TEST(PrintedSeams, AMisplacedPieceShowsOnThePrintNotOnTheContone) {
  const json planned = run_top("planned", {}, true);
  ASSERT_EQ(planned["state"], "done");
  // The demo's top-strokes run (DemoReport leaves it to this test): its report matches the schema.
  const auto valid = validate_report(fs::path(planned["_out"].get<std::string>()) / "report.json");
  EXPECT_EQ(valid.exit_code, 0) << valid.output;
  EXPECT_GT(planned["estimate"]["print_time_s"].get<double>(), 0);
  EXPECT_GT(planned["measured"]["print_time_s"].get<double>(), 0);
  EXPECT_GT(planned["measured"]["fabric_length_mm"].get<double>(), 0);
  ASSERT_TRUE(planned["seams_printed"]["de00_mean"].is_number()) << planned["seams_printed"].dump();
  // The same pairs, less those whose aperture would reach a seam-line corner or the cut line.
  EXPECT_LE(planned["seams_printed"]["samples"].get<int>(), planned["seams"]["samples"].get<int>());
  EXPECT_GT(planned["seams_printed"]["samples"].get<int>(), 0.8 * planned["seams"]["samples"].get<int>());
  EXPECT_EQ(planned["seams_printed"]["fabric"], "fabric-lab.tif");
  EXPECT_GT(planned["allowance_printed"]["samples"].get<int>(), 1000);
  // Printed as planned, the seams match on the fabric too.
  EXPECT_LT(planned["seams_printed"]["de00_mean"].get<double>(), 1.0);
  EXPECT_LT(planned["seams_printed"]["de00_p95"].get<double>(), 2.5);
  const double planned_worst = worst_seam_with(planned, "front_l");
  EXPECT_LT(planned_worst, 1.0);

  for (const std::string hook : {"front_l:3:0:0", "front_l:0:0:1"}) {
    SCOPED_TRACE(hook);
    const json off = run_top(hook == "front_l:3:0:0" ? "shifted" : "turned", {"--debug-misplace", hook});
    ASSERT_EQ(off["state"], "done");
    // The contone figure is blind to it: the same as planned.
    EXPECT_EQ(off["seams"]["samples"], planned["seams"]["samples"]);
    EXPECT_NEAR(off["seams"]["de00_mean"].get<double>(), planned["seams"]["de00_mean"].get<double>(), 1e-9);
    // The printed one sees it, on the seams of that piece.
    const double worst = worst_seam_with(off, "front_l");
    EXPECT_GT(worst, 2.5);
    EXPECT_GT(worst, 5 * planned_worst);
    EXPECT_GT(off["allowance_printed"]["de00_mean"].get<double>(),
              planned["allowance_printed"]["de00_mean"].get<double>());
  }

  // The gamut section, through the default CMYK profile, with its soft proof beside marker.png.
  const json& g = planned["gamut"];
  EXPECT_EQ(g["profile_source"], "default");
  EXPECT_GT(g["printed_pixels"].get<int>(), 0);
  EXPECT_GE(g["out_of_gamut_share"].get<double>(), 0.0);
  EXPECT_LE(g["out_of_gamut_share"].get<double>(), 1.0);
  EXPECT_GT(g["worst_de00"].get<double>(), 0.0);
  EXPECT_TRUE(fs::is_regular_file(fs::path(planned["_out"].get<std::string>()) / "marker-proof.png"));
  EXPECT_TRUE(fs::is_regular_file(fs::path(planned["_out"].get<std::string>()) / "marker-gamut.png"));
}

TEST(PrintedSeams, WithoutAPrintedFabricTheFiguresSayWhy) {
  const json rep = run_top("no-printer", {"--printer", "none"});
  ASSERT_EQ(rep["state"], "done");
  EXPECT_TRUE(rep["seams"]["de00_mean"].is_number());
  EXPECT_TRUE(rep["seams_printed"]["de00_mean"].is_null());
  EXPECT_EQ(rep["seams_printed"]["samples"], 0);
  EXPECT_NE(rep["seams_printed"]["reason"].get<std::string>().find("not printsim"), std::string::npos);
  EXPECT_TRUE(rep["allowance_printed"]["reason"].is_string());
  const auto v = validate_report(fs::path(rep["_out"].get<std::string>()) / "report.json");
  EXPECT_EQ(v.exit_code, 0) << v.output;
}

TEST(PrintedSeams, ABadMisplaceHookIsRefused) {
  const fs::path out = scratch_dir("printed-seams-bad") / "out";
  auto r = run_command({(bin_dir() / "printctl").string(), "run", (source_dir() / "examples/top-strokes").string(),
                        "--out", out.string(), "--debug-misplace", "front_l:3:x:0", "--printer", "none"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("PIECE:DX_MM:DY_MM:DEG"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace tp::test
