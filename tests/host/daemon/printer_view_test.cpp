// tests/host/daemon/printer_view_test.cpp: printd's live printer view: events only on a change of
// state or condition (or a fired cue), and the snapshot's buffer fill, faults and cue log.
#include "host/daemon/printer_view.h"

#include <gtest/gtest.h>

namespace tp::host {
namespace {

PrinterLive live(device::PrinterState state, device::PrinterCondition condition, std::uint16_t free_slots,
                 std::uint32_t free_bytes) {
  PrinterLive l;
  l.identity.model = "tp-sim-1600";
  l.identity.ieee1284_id = "MFG:TextilePrint;MDL:TP-SIM-1600;CMD:TPWP;";
  l.identity.swath_slots = 8;
  l.identity.swath_buffer_bytes = 1000;
  l.status.state = state;
  l.status.condition = condition;
  l.status.free_slots = free_slots;
  l.status.free_bytes = free_bytes;
  l.status.job_id = 5;
  return l;
}

TEST(PrinterView, EventsOnlyOnChangeAndSnapshotShowsTheFault) {
  PrinterView v;
  EXPECT_TRUE(v.snapshot().is_null());
  using S = device::PrinterState;
  using C = device::PrinterCondition;
  ASSERT_TRUE(v.update(live(S::kPrinting, C::kNone, 6, 750)));
  EXPECT_FALSE(v.update(live(S::kPrinting, C::kNone, 5, 500)));  // buffer only: no event
  auto ev = v.update(live(S::kPaused, C::kCoverOpen, 5, 500));
  ASSERT_TRUE(ev);
  EXPECT_EQ((*ev)["condition"], "cover_open");
  EXPECT_EQ((*ev)["faults"][0]["stops_job"], false);
  const auto snap = v.snapshot();
  EXPECT_EQ(snap["state"], "paused");
  EXPECT_EQ(snap["faults"][0]["condition"], "cover_open");
  EXPECT_EQ(snap["swath_buffer"]["slots_used"], 3);
  EXPECT_DOUBLE_EQ(snap["swath_buffer"]["fill"].get<double>(), 0.5);
  EXPECT_EQ(snap["counters"]["fault_changes"], 1);
  EXPECT_EQ(snap["identity"]["model"], "tp-sim-1600");

  PrinterLive cue = live(S::kPaused, C::kCoverOpen, 5, 500);
  cue.fired_cue = CueRecord{1, device::CueKind::kNotch, 1000, 20, true, 1010};
  auto cev = v.update(cue);
  ASSERT_TRUE(cev);
  EXPECT_EQ((*cev)["cue"]["line"], "notch_mark");
  ASSERT_EQ(v.snapshot()["cutter_lines"].size(), 1u);
  EXPECT_EQ(v.snapshot()["cutter_lines"][0]["fired_at_um"], 1010);

  ASSERT_TRUE(v.update(live(S::kFault, C::kMediaJam, 5, 500)));
  EXPECT_EQ(v.snapshot()["faults"][0]["stops_job"], true);
}

}  // namespace
}  // namespace tp::host
