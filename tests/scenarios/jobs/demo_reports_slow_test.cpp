// tests/scenarios/jobs/demo_reports_slow_test.cpp: every example job the demo prints gives a
// report that the JSON Schema (docs/schema/report.schema.json) accepts, read by python3-jsonschema,
// with the estimate made before printing and the figures measured after.
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

class DemoReport : public ::testing::TestWithParam<const char*> {};

TEST_P(DemoReport, PrintedOnTheSimulatorItMatchesTheSchema) {
  const std::string name = GetParam();
  const fs::path out = scratch_dir("demo_report_" + name) / "out";
  auto r = run_command(
      {(bin_dir() / "printctl").string(), "run", (source_dir() / "examples" / name).string(), "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto valid = validate_report(out / "report.json");
  EXPECT_EQ(valid.exit_code, 0) << valid.output;
  const auto rep = read_json(out / "report.json");
  EXPECT_EQ(rep["state"], "done");
  EXPECT_GT(rep["estimate"]["print_time_s"].get<double>(), 0);
  EXPECT_GT(rep["measured"]["print_time_s"].get<double>(), 0);
  EXPECT_GT(rep["measured"]["fabric_length_mm"].get<double>(), 0);
}

// shirt-front-flat is OutputReaders' job (output_readers_test.cpp), top-strokes PrintedSeams'
// (printed_seams_slow_test.cpp runs the same command and checks the same).
INSTANTIATE_TEST_SUITE_P(Examples, DemoReport,
                         ::testing::Values("skirt-marbling", "dress-projection", "blouse-projection", "order-team-kit"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace tp::test
