// tests/scenarios/jobs/order_patterns_slow_test.cpp: an order of an imported pattern, one FreeSewing
// export per size (../shared/data/freesewing), printed flat: every size's pieces in one marker.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

TEST(OrderPatterns, OnePatternFilePerSizeAllInOneMarker) {
  const fs::path src = shared_data_dir() / "freesewing";
  if (!fs::exists(src / "penelope-cisFemaleAdult28.svg")) GTEST_SKIP() << "no FreeSewing exports in " << src;
  const fs::path dir = scratch_dir("order_patterns");
  fs::create_directories(dir / "job");
  for (const char* n : {"28", "34", "42"})
    fs::copy_file(src / ("penelope-cisFemaleAdult" + std::string(n) + ".svg"),
                  dir / "job" / ("p" + std::string(n) + ".svg"), fs::copy_options::overwrite_existing);
  std::ofstream(dir / "job" / "job.json") << R"({"format": "tp-job/1", "name": "penelope-order",
    "garment": {"pattern": "p34.svg", "size": "34"},
    "design": {"layers": [{"type": "text", "name": "label", "text": "{name}", "size": "3 cm",
                           "centre": [0, 0, 10], "normal": [0, 0, 1]}]},
    "order": {"sizes": [{"size": "28", "quantity": 1, "pattern": "p28.svg"},
                        {"size": "34", "quantity": 1, "pattern": "p34.svg"},
                        {"size": "42", "quantity": 1, "pattern": "p42.svg"}],
              "copies": [{"name": "A"}, {"name": "B"}, {"name": "C"}]},
    "marker": {"fabric_width": "1.5 m", "budget": {"iterations": 2000}},
    "print": {"dpi": 50, "preview_dpi": 20}})";
  const fs::path out = dir / "out";
  auto r = run_command(
      {(bin_dir() / "printctl").string(), "run", (dir / "job").string(), "--printer", "none", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(out / "report.json");
  const auto rep = nlohmann::json::parse(in);
  ASSERT_EQ(rep["state"], "done");
  ASSERT_EQ(rep["sizes"].size(), 3u);
  size_t pieces = 0;
  for (const auto& s : rep["sizes"]) {
    pieces += s["pattern"]["piece_count"].get<size_t>();
    // No body to map through: the base prints as given, the others too ("unmapped").
    EXPECT_EQ(s["reprojection"]["placement"], s["size"] == "34" ? "base" : "unmapped");
  }
  EXPECT_EQ(rep["piece_count"], pieces);
  ASSERT_EQ(rep["marker"]["markers"].size(), 1u);
  EXPECT_EQ(rep["marker"]["markers"][0]["pieces"], pieces);
  EXPECT_EQ(rep["copies"][2]["size"], "42");
  EXPECT_EQ(rep["copies"][2]["texts"][0], "C");

  // A size whose pattern file is missing is named before anything runs.
  std::ifstream jin(dir / "job" / "job.json");
  auto job = nlohmann::json::parse(jin);
  job["order"]["sizes"][2]["pattern"] = "p44.svg";
  std::ofstream(dir / "job" / "job.json") << job.dump();
  auto bad = run_command({(bin_dir() / "printctl").string(), "validate", (dir / "job").string()});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("/order/sizes/2/pattern"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("p44.svg"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace tp::test
