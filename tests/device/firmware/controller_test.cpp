// tests/device/firmware/controller_test.cpp: the printer controller's state machine, driven by
// the real host link over the in-process transport: jobs, credits, cues, pauses, faults, aborts.
#include "device/firmware/controller.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "device/firmware/firmware_transport.h"
#include "device/protocol/host_link.h"
#include "device/swath/packbits.h"

namespace tp::device {
namespace {

using std::chrono::milliseconds;

// Records what the printer put on the fabric.
struct FakeFabric : PrintSink {
  std::vector<std::pair<std::uint32_t, std::int64_t>> printed;  // swath, row
  std::vector<std::vector<std::uint8_t>> raw;
  int started = 0, resumed = 0;
  std::vector<JobReportMsg> reports;
  void job_started(const JobBeginMsg&, bool r) override { (r ? resumed : started)++; }
  void swath_printed(const SwathHeader& h, std::span<const std::uint8_t> data, std::int64_t row) override {
    printed.emplace_back(h.index, row);
    raw.emplace_back(data.begin(), data.end());
  }
  void job_finished(const JobReportMsg& r) override { reports.push_back(r); }
};

PrinterModel small_model() {
  PrinterModel m;
  m.nozzles_per_ink = 32;
  m.swath_buffer_slots = 2;
  m.swath_buffer_bytes = 1u << 20;
  return m;
}

Swath make_swath(std::uint32_t index, bool pack = true) {
  Swath s;
  auto& h = s.header;
  h.index = index;
  h.rows = 32;
  h.first_row = index * 32;
  h.width_px = 40;
  h.x_start_px = 8;
  h.channels = 4;
  h.bits_per_pixel = 2;
  h.feed_before_um = index ? 1355 : 0;  // 32 rows at 600 dpi
  h.raw_bytes = static_cast<std::uint32_t>(swath_raw_bytes(h));
  std::vector<std::uint8_t> raw(h.raw_bytes);
  for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = static_cast<std::uint8_t>((i + index) % 7 == 0 ? 0x55 : 0);
  if (pack) {
    h.compression = SwathCompression::kPackBits;
    packbits_encode(raw, s.data);
  } else {
    s.data = raw;
  }
  return s;
}

struct Rig {
  FakeFabric fabric;
  PrinterController printer;
  FirmwareTransport transport;
  HostLink link;
  std::vector<FirmwareEvent> events;
  explicit Rig(PrinterModel m = small_model(), FirmwareOptions fo = {})
      : printer(std::move(m), &fabric, fo), transport(printer), link(transport) {
    printer.set_observer([this](const FirmwareEvent& e) { events.push_back(e); });
  }
  StatusMsg status() {
    auto s = link.query_status(milliseconds(2000));
    EXPECT_TRUE(s) << (s ? "" : s.error().message);
    return s ? *s : StatusMsg{};
  }
  void begin(std::uint64_t id = 42, std::uint32_t first = 0) {
    ASSERT_TRUE(link.handshake());
    ASSERT_TRUE(link.send_msg(MessageType::kJobBegin, JobBeginMsg{id, "test", first, 0}));
  }
};

TEST(Controller, PrintsAJobAndReportsItsCounters) {
  Rig r;
  r.begin();
  for (std::uint32_t i = 0; i < 2; ++i) ASSERT_TRUE(r.link.send_swath(make_swath(i, i == 0)));
  ASSERT_TRUE(r.link.send_msg(MessageType::kJobEnd, JobEndMsg{2, 5000}));
  auto s = r.status();
  EXPECT_EQ(s.state, PrinterState::kIdle);
  EXPECT_EQ(s.last_job_id, 42u);
  EXPECT_EQ(s.last_outcome, JobOutcome::kCompleted);
  ASSERT_EQ(r.fabric.printed.size(), 2u);
  EXPECT_EQ(r.fabric.printed[1], (std::pair<std::uint32_t, std::int64_t>{1, 32}));
  // Packed and raw swaths decode to the same layout.
  EXPECT_EQ(r.fabric.raw[0].size(), make_swath(0).header.raw_bytes);
  ASSERT_EQ(r.fabric.reports.size(), 1u);
  const auto& rep = r.fabric.reports[0];
  EXPECT_EQ(rep.swaths_printed, 2u);
  EXPECT_EQ(rep.feed_travel_um, 1355 + 5000);
  EXPECT_GT(rep.print_time_us, 0u);
  // 0x55 = four drops of level 1 per byte.
  std::uint64_t expect = 0;
  for (std::uint32_t i = 0; i < 2; ++i)
    for (std::size_t k = 0; k < r.fabric.raw[i].size() / 4; ++k) expect += r.fabric.raw[i][k] == 0x55 ? 4 : 0;
  EXPECT_EQ(rep.drops_per_ink[0], expect);
  EXPECT_EQ(r.printer.row_mismatches(), 0u);
}

TEST(Controller, ALostJobIsReportedWithWhatIsOnTheFabricAndSurvivesAPowerCycle) {
  Rig r;
  r.begin();
  for (std::uint32_t i = 0; i < 2; ++i) ASSERT_TRUE(r.link.send_swath(make_swath(i)));
  auto before = r.status();
  EXPECT_EQ(before.printed_next, 2u);
  EXPECT_EQ(before.printed_fabric_um, 1355) << "swath 1 was laid after one feed";
  r.printer.lose_job("power loss");
  // The memory a power cycle keeps, restored into a new controller: the same report.
  Rig after;
  after.printer.restore(r.printer.nonvolatile());
  ASSERT_TRUE(after.link.handshake());
  auto s = after.status();
  EXPECT_EQ(s.job_id, 0u);
  EXPECT_EQ(s.last_job_id, 42u);
  EXPECT_EQ(s.last_outcome, JobOutcome::kLost);
  EXPECT_EQ(s.last_printed_next, 2u);
  EXPECT_EQ(s.last_printed_fabric_um, 1355);
  EXPECT_EQ(s.last_fabric_pos_um, 1355);
  // The host reopens it at swath 2 with the fabric where it stands; counters go on.
  ASSERT_TRUE(after.link.send_msg(MessageType::kJobBegin, JobBeginMsg{42, "test", 2, 0, 1355}));
  ASSERT_TRUE(after.link.send_swath(make_swath(2)));
  ASSERT_TRUE(after.link.send_msg(MessageType::kJobEnd, JobEndMsg{3, 0}));
  auto end = after.status();
  EXPECT_EQ(end.last_outcome, JobOutcome::kCompleted);
  ASSERT_EQ(after.fabric.reports.size(), 1u);
  EXPECT_EQ(after.fabric.reports[0].swaths_printed, 3u);
  EXPECT_EQ(after.fabric.reports[0].first_swath, 0u);
  EXPECT_EQ(after.fabric.reports[0].feed_travel_um, 2 * 1355);
  EXPECT_EQ(end.last_fabric_pos_um, 2 * 1355);
  EXPECT_EQ(after.printer.row_mismatches(), 0u);
}

TEST(Controller, RefusesASwathSentWithoutCredit) {
  FirmwareOptions slow;
  slow.speed = 1e-6;  // passes take "forever": the buffer fills
  Rig r(small_model(), slow);
  r.begin();
  ASSERT_TRUE(r.link.send_swath(make_swath(0)));
  ASSERT_TRUE(r.link.send_swath(make_swath(1)));
  auto s = r.status();
  EXPECT_EQ(s.free_slots, 0);
  ASSERT_TRUE(r.link.send_swath(make_swath(2)));  // a broken host ignoring credits
  (void)r.status();
  auto rej = r.link.take_reject();
  ASSERT_TRUE(rej);
  EXPECT_EQ(rej->code, ErrorCode::kBufferFull);
  EXPECT_NE(rej->message.find("swath 2"), std::string::npos) << rej->message;
  EXPECT_EQ(r.status().swath_next, 2u);
}

TEST(Controller, RefusesSwathsThatDoNotFitThePrinter) {
  Rig r;
  r.begin();
  Swath s = make_swath(0);
  s.header.channels = 3;
  s.header.raw_bytes = static_cast<std::uint32_t>(swath_raw_bytes(s.header));
  ASSERT_TRUE(r.link.send_swath(s));
  (void)r.status();
  auto rej = r.link.take_reject();
  ASSERT_TRUE(rej);
  EXPECT_NE(rej->message.find("3 channels, printer has 4 inks"), std::string::npos) << rej->message;
  Swath gap = make_swath(5);
  ASSERT_TRUE(r.link.send_swath(gap));
  (void)r.status();
  rej = r.link.take_reject();
  ASSERT_TRUE(rej);
  EXPECT_EQ(rej->code, ErrorCode::kSequenceError);
  EXPECT_TRUE(r.fabric.printed.empty());
}

TEST(Controller, HoldsTheFabricAtACueUntilTheHostFiresIt) {
  Rig r;
  r.begin();
  ASSERT_TRUE(r.link.send_msg(MessageType::kCutterCue, CutterCueMsg{1, CueKind::kCut, 1000, 0}));
  ASSERT_TRUE(r.link.send_swath(make_swath(0)));
  ASSERT_TRUE(r.link.send_swath(make_swath(1)));  // its feed (1355 um) passes the cue
  auto s = r.status();
  EXPECT_EQ(s.state, PrinterState::kWaitingForCue);
  EXPECT_EQ(s.cue_waiting, 1u);
  EXPECT_EQ(s.fabric_pos_um, 1355);
  EXPECT_EQ(r.fabric.printed.size(), 1u) << "swath 1 waits until the cue is fired";
  ASSERT_TRUE(r.link.send_msg(MessageType::kCueDone, CueDoneMsg{1}));
  s = r.status();
  EXPECT_EQ(s.cue_waiting, 0u);
  EXPECT_EQ(r.fabric.printed.size(), 2u);
}

TEST(Controller, PausesForAConditionAndResumesWhenItClears) {
  Rig r;
  r.begin();
  r.printer.set_condition(PrinterCondition::kInkLow, true);
  ASSERT_TRUE(r.link.send_swath(make_swath(0)));
  auto s = r.status();
  EXPECT_EQ(s.state, PrinterState::kPaused);
  EXPECT_EQ(s.condition, PrinterCondition::kInkLow);
  EXPECT_EQ(s.swath_next, 1u) << "a paused printer still takes data";
  EXPECT_TRUE(r.fabric.printed.empty());
  r.printer.set_condition(PrinterCondition::kInkLow, false);
  s = r.status();
  EXPECT_EQ(s.printed_next, 1u);
}

TEST(Controller, AFaultStopsTheJobUnprintedUntilAborted) {
  Rig r;
  r.begin();
  r.printer.set_observer([&](const FirmwareEvent& e) {
    if (e.kind == FirmwareEventKind::kSwathPrinting && e.swath == 1) r.printer.raise_fault(PrinterCondition::kMediaJam);
  });
  for (std::uint32_t i = 0; i < 2; ++i) ASSERT_TRUE(r.link.send_swath(make_swath(i)));
  auto s = r.status();
  EXPECT_EQ(s.state, PrinterState::kFault);
  EXPECT_EQ(s.condition, PrinterCondition::kMediaJam);
  EXPECT_EQ(s.printed_next, 1u);
  ASSERT_TRUE(r.link.send_msg(MessageType::kAbort, AbortMsg{"jam"}));
  s = r.status();
  EXPECT_EQ(s.state, PrinterState::kIdle);
  EXPECT_EQ(s.last_outcome, JobOutcome::kFailed);
  ASSERT_EQ(r.fabric.reports.size(), 1u);
  EXPECT_EQ(r.fabric.reports[0].swaths_printed, 1u);
  EXPECT_EQ(r.fabric.reports[0].condition, PrinterCondition::kMediaJam);
}

TEST(Controller, KeepsTheJobAcrossALinkResetAndResumes) {
  Rig r;
  r.begin(7);
  ASSERT_TRUE(r.link.send_swath(make_swath(0)));
  (void)r.status();
  // A new connection: handshake again and re-attach to job 7.
  ASSERT_TRUE(r.link.handshake());
  ASSERT_TRUE(r.link.send_msg(MessageType::kJobBegin, JobBeginMsg{7, "test", 1, 0}));
  auto s = r.status();
  EXPECT_EQ(s.job_id, 7u);
  EXPECT_EQ(s.swath_next, 1u);
  EXPECT_EQ(r.fabric.resumed, 1);
  // A second job while the first is open is refused with a reason.
  ASSERT_TRUE(r.link.send_msg(MessageType::kJobBegin, JobBeginMsg{8, "other", 0, 0}));
  (void)r.status();
  auto rej = r.link.take_reject();
  ASSERT_TRUE(rej);
  EXPECT_NE(rej->message.find("job 7"), std::string::npos) << rej->message;
}

TEST(Controller, ModelledTimeFollowsCarriageAndFeedSpeeds) {
  PrinterModel fast = small_model(), slow = small_model();
  slow.carriage_speed_mm_s = fast.carriage_speed_mm_s / 2;
  std::uint64_t t_fast = 0, t_slow = 0;
  for (auto* m : {&fast, &slow}) {
    Rig r(*m);
    r.begin();
    ASSERT_TRUE(r.link.send_swath(make_swath(0)));
    ASSERT_TRUE(r.link.send_msg(MessageType::kJobEnd, JobEndMsg{1, 0}));
    (void)r.status();
    ASSERT_EQ(r.fabric.reports.size(), 1u);
    (m == &fast ? t_fast : t_slow) = r.fabric.reports[0].print_time_us;
  }
  // One pass covers 40 mm of ramps each side plus the swath: halving the speed adds ~54 ms.
  EXPECT_GT(t_slow, t_fast + 40000);
  EXPECT_LT(t_slow, t_fast + 70000);
}

TEST(Controller, SpeaksOnlyItsProtocolVersion) {
  PrinterModel m = small_model();
  m.protocol_version = 2;
  Rig r(m);
  auto id = r.link.handshake();
  ASSERT_FALSE(id);
  EXPECT_EQ(id.error().code, ErrorCode::kIncompatiblePrinter);
  EXPECT_NE(id.error().message.find("protocol version 2"), std::string::npos) << id.error().message;
  EXPECT_NE(id.error().message.find("this host speaks 1"), std::string::npos);
}

}  // namespace
}  // namespace tp::device
