// tests/simulator/printsim/printer_memory_test.cpp: the printer's memory file round-trips, a
// missing file is an empty memory, and a damaged one is refused naming the file.
#include "simulator/printsim/printer_memory.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/paths.h"

namespace tp::sim {
namespace {

TEST(PrinterMemory, RoundTripsALostJob) {
  const auto dir = test::scratch_dir("printer-memory");
  device::NonVolatileState nv;
  nv.last_job_id = 9;
  nv.last_outcome = device::JobOutcome::kLost;
  nv.last_printed_next = 4;
  nv.last_printed_fabric_um = 1200;
  nv.last_fabric_pos_um = 1500;
  device::JobReportMsg r;
  r.job_id = 9;
  r.name = "skirt";
  r.swaths_printed = 4;
  r.drops_per_ink = {1, 2, 3, 4};
  nv.last_report = r;
  ASSERT_TRUE(save_printer_memory(dir / "m.json", nv));
  auto back = load_printer_memory(dir / "m.json");
  ASSERT_TRUE(back) << back.error().what();
  EXPECT_EQ(back->last_job_id, 9u);
  EXPECT_EQ(back->last_outcome, device::JobOutcome::kLost);
  EXPECT_EQ(back->last_printed_next, 4u);
  EXPECT_EQ(back->last_printed_fabric_um, 1200);
  EXPECT_EQ(back->last_fabric_pos_um, 1500);
  ASSERT_TRUE(back->last_report);
  EXPECT_EQ(back->last_report->drops_per_ink, r.drops_per_ink);
  EXPECT_EQ(back->last_report->name, "skirt");
}

TEST(PrinterMemory, AMissingFileIsEmptyAndADamagedOneIsRefused) {
  const auto dir = test::scratch_dir("printer-memory-bad");
  auto none = load_printer_memory(dir / "absent.json");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->last_job_id, 0u);
  std::ofstream(dir / "bad.json") << R"({"last_job_id": 1, "last_outcome": 9})";
  auto bad = load_printer_memory(dir / "bad.json");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().what().find("bad.json"), std::string::npos) << bad.error().what();
}

}  // namespace
}  // namespace tp::sim
