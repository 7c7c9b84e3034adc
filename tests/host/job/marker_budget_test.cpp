// tests/host/job/marker_budget_test.cpp: the marker's nesting budget in job.json: seconds or
// iterations, and `reproducible`, with named refusals.
#include <gtest/gtest.h>

#include <fstream>

#include "host/job/manifest.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

Result<Job> load_marker(const std::string& marker_fields) {
  const auto dir = tp::test::scratch_dir("marker_budget");
  std::ofstream(dir / "pattern.json") << "{}";
  std::ofstream(dir / "job.json") << R"({"format": "tp-job/1", "name": "b", "garment": {"pattern": "pattern.json"},
    "marker": {"fabric_width": "1.5 m")" + marker_fields + "}}";
  auto pkg = JobPackage::open(dir, dir / "unused");
  if (!pkg) return std::unexpected(pkg.error());
  return load_job(*pkg);
}

TEST(MarkerBudget, IterationsSecondsAndReproducible) {
  auto it = load_marker(R"(, "budget": {"iterations": 500})");
  ASSERT_TRUE(it) << it.error().message;
  EXPECT_EQ(it->marker.iterations, 500);
  auto secs = load_marker(R"(, "budget": {"seconds": 2.5})");
  ASSERT_TRUE(secs) << secs.error().message;
  EXPECT_EQ(secs->marker.iterations, 0);
  EXPECT_DOUBLE_EQ(secs->marker.time_limit_s, 2.5);
  auto rep = load_marker(R"(, "reproducible": true)");
  ASSERT_TRUE(rep) << rep.error().message;
  EXPECT_EQ(rep->marker.iterations, 20000);
  // With no budget the marker is reproducible; `reproducible: false` alone gives the default seconds.
  auto plain = load_marker("");
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->marker.iterations, 20000);
  auto timed = load_marker(R"(, "reproducible": false)");
  ASSERT_TRUE(timed);
  EXPECT_EQ(timed->marker.iterations, 0);
  EXPECT_DOUBLE_EQ(timed->marker.time_limit_s, 5);
  auto seconds = load_marker(R"(, "time_limit_s": 3)");
  ASSERT_TRUE(seconds);
  EXPECT_EQ(seconds->marker.iterations, 0);
}

TEST(MarkerBudget, ContradictionsAreRefusedNamingTheField) {
  for (const char* bad : {R"(, "budget": {"seconds": 1, "iterations": 5})", R"(, "budget": {})",
                          R"(, "budget": {"iterations": 0})", R"(, "budget": {"minutes": 3})",
                          R"(, "reproducible": true, "time_limit_s": 4)", R"(, "budget": 5)"}) {
    auto job = load_marker(bad);
    ASSERT_FALSE(job) << bad;
    EXPECT_NE(job.error().message.find("/marker/"), std::string::npos) << bad << ": " << job.error().message;
  }
}

}  // namespace
}  // namespace tp::host
