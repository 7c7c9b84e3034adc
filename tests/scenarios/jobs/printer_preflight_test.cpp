// tests/scenarios/jobs/printer_preflight_test.cpp: a job planned for another printer model than the
// one connected fails at intake, naming the difference, before its other stages run; a job for
// the connected printer records that its printer was checked.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kJob = source_dir() / "examples/shirt-front-flat";

// The printer the job plans for (as `printctl run` would start printsim with), with `from`
// replaced by `to`, written to `path`.
void write_model_with(const fs::path& path, const std::string& from, const std::string& to) {
  auto m = run_command({(bin_dir() / "printctl").string(), "printer-model", kJob.string(), "--out", path.string()});
  ASSERT_EQ(m.exit_code, 0) << m.output;
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, from.size(), to);
  std::ofstream(path) << text;
}

struct FlatRun {
  int exit_code = 0;
  std::string output;
  json report;
};

// Runs examples/shirt-front-flat under printsim emulating the job's printer with `from` replaced
// by `to` in its model.
FlatRun run_flat_job(const std::string& name, const std::string& from, const std::string& to) {
  const fs::path dir = scratch_dir(name);
  const fs::path model = dir / "printer.tpm";
  write_model_with(model, from, to);
  const fs::path out = dir / "out";
  auto r = run_command({(bin_dir() / "printsim").string(), "run", "--out", (dir / "sim").string(), "--no-fabric",
                        "--printer", model.string(), "--", (bin_dir() / "printctl").string(), "run", kJob.string(),
                        "--out", out.string()});
  FlatRun run{r.exit_code, r.output, json()};
  std::ifstream in(out / "report.json");
  if (in) run.report = json::parse(in);
  return run;
}

TEST(PrinterPreflight, AJobForAnotherPrinterFailsAtIntakeBeforeItsOtherStages) {
  const FlatRun run = run_flat_job("printer-preflight-other", "nozzles_per_ink = 1280", "nozzles_per_ink = 640");
  EXPECT_NE(run.exit_code, 0) << run.output;
  ASSERT_TRUE(run.report.is_object()) << run.output;
  EXPECT_EQ(run.report["state"], "failed");
  const std::string error = run.report.value("error", "");
  EXPECT_NE(error.find("640 nozzles per ink, the job plans for 1280"), std::string::npos) << error;
  for (const json& s : run.report["stages"]) {
    if (s["stage"] == "intake") {
      EXPECT_EQ(s["state"], "failed") << s.dump();
    } else if (s["stage"] == "pattern" || s["stage"] == "design" || s["stage"] == "print") {
      EXPECT_TRUE(s["wall_s"].is_null()) << "ran after a failed printer check: " << s.dump();
    }
  }
}

TEST(PrinterPreflight, AJobForTheConnectedPrinterRecordsTheCheck) {
  const FlatRun run = run_flat_job("printer-preflight-same", "carriage_origin = left", "carriage_origin = left");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  ASSERT_TRUE(run.report.is_object()) << run.output;
  EXPECT_EQ(run.report["state"], "done");
  EXPECT_EQ(run.report["intake"].value("printer_checked", false), true) << run.report["intake"].dump();
}

}  // namespace
}  // namespace tp::test
