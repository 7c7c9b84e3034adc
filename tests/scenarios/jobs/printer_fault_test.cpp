// tests/scenarios/jobs/printer_fault_test.cpp: a printer fault in the middle of a whole job
// (`printctl run` under printsim with a fault scenario) reaches the operator and report.json as
// that printer fault, naming it and where the print stopped, not as a RIP or pipeline error.
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

struct FaultCase {
  const char* fault;  ///< printsim's fault type (docs/simulator.md)
  const char* words;  ///< how the operator message names the fault
};

// Names the case in test output (gtest would otherwise print its bytes).
void PrintTo(const FaultCase& c, std::ostream* os) { *os << c.fault; }

class PrinterFaultJob : public ::testing::TestWithParam<FaultCase> {};

TEST_P(PrinterFaultJob, IsReportedAsThePrintersFault) {
  const FaultCase& c = GetParam();
  const fs::path dir = scratch_dir(std::string("printer-fault-") + c.fault);
  // The fault strikes as the second swath starts, so one swath is on the fabric.
  const fs::path scenario = dir / "scenario.json";
  std::ofstream(scenario) << json{{"faults", {{{"type", c.fault}, {"at_swath", 1}}}}}.dump();
  const fs::path job = source_dir() / "examples/shirt-front-flat";
  // printsim emulates the printer the job plans for, as `printctl run` arranges when it starts it.
  const fs::path model = dir / "model.tpm";
  auto m = run_command({(bin_dir() / "printctl").string(), "printer-model", job.string(), "--out", model.string()});
  ASSERT_EQ(m.exit_code, 0) << m.output;

  const fs::path out = dir / "out";
  auto r = run_command({(bin_dir() / "printsim").string(), "run", "--out", (dir / "sim").string(), "--no-fabric",
                        "--printer", model.string(), "--scenario", scenario.string(), "--",
                        (bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string()});
  EXPECT_NE(r.exit_code, 0) << r.output;
  const std::string expected = std::string("print: printer fault: ") + c.words;
  EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;

  const json rep = read_json(out / "report.json");
  EXPECT_EQ(rep["state"], "failed");
  const std::string error = rep.value("error", "");
  EXPECT_EQ(error.rfind(expected, 0), 0u) << error;
  EXPECT_NE(error.find("below 1 printed"), std::string::npos) << "says how far the print got: " << error;
  for (const json& s : rep["stages"])
    if (s["stage"] == "print") EXPECT_EQ(s["state"], "failed");
}

INSTANTIATE_TEST_SUITE_P(Faults, PrinterFaultJob,
                         ::testing::Values(FaultCase{"head_strike", "head strike"},
                                           FaultCase{"media_jam", "media jam"}),
                         [](const auto& info) { return std::string(info.param.fault); });

}  // namespace
}  // namespace tp::test
