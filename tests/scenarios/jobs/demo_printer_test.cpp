// tests/scenarios/jobs/demo_printer_test.cpp: every job scripts/demo sends to its one printsim plans for
// the printer that printsim emulates, so none of them fails at the print stage after all its work.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

// The words of a bash array assignment `NAME=(a b c)` in the script.
std::vector<std::string> bash_array(const std::string& script, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(script, m, std::regex("\n" + name + "=\\(([^)]*)\\)"))) return {};
  std::istringstream words(m[1].str());
  std::vector<std::string> out;
  for (std::string w; words >> w;) out.push_back(w);
  return out;
}

// The printer model file `printctl printer-model` writes for an example job.
std::string printer_model(const std::string& example) {
  const fs::path out = scratch_dir("demo_printer") / (example + ".txt");
  auto r = run_command({(bin_dir() / "printctl").string(), "printer-model",
                        (source_dir() / "examples" / example).string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 0) << example << ": " << r.output;
  return read_text(out);
}

TEST(DemoPrinter, EveryDemoJobPlansForThePrinterTheDemoStarts) {
  const std::string script = read_text(source_dir() / "scripts" / "demo");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(script, m, std::regex("printer-model \"\\$TP_ROOT/examples/([A-Za-z0-9_-]+)\"")))
      << "scripts/demo no longer writes its printer model from an example";
  const std::string demo_printer = printer_model(m[1].str());
  ASSERT_FALSE(demo_printer.empty());
  std::vector<std::string> jobs = bash_array(script, "SOCKET_JOBS");
  const auto hot = bash_array(script, "HOT_JOBS");
  jobs.insert(jobs.end(), hot.begin(), hot.end());
  ASSERT_GE(jobs.size(), 2u) << "scripts/demo's SOCKET_JOBS/HOT_JOBS were not found";
  for (const auto& job : jobs)
    EXPECT_EQ(printer_model(job), demo_printer)
        << "examples/" << job << " plans for another printer than the demo's (" << m[1].str() << "'s)";
}

}  // namespace
}  // namespace tp::test
