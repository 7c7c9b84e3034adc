// tests/device/protocol/host_link_test.cpp: the host link's reliable delivery against the real
// firmware when frames are dropped or corrupted on the way, and on a dead link.
#include "device/protocol/host_link.h"

#include <gtest/gtest.h>

#include <set>

#include "device/firmware/controller.h"
#include "device/firmware/firmware_transport.h"

namespace tp::device {
namespace {

using std::chrono::milliseconds;

struct Counting : PrintSink {
  std::vector<std::uint32_t> printed;
  void job_started(const JobBeginMsg&, bool) override {}
  void swath_printed(const SwathHeader& h, std::span<const std::uint8_t>, std::int64_t) override {
    printed.push_back(h.index);
  }
  void job_finished(const JobReportMsg&) override {}
};

Swath raw_swath(std::uint32_t i) {
  Swath s;
  s.header.index = i;
  s.header.rows = 16;
  s.header.first_row = i * 16;
  s.header.width_px = 64;
  s.header.channels = 4;
  s.header.raw_bytes = static_cast<std::uint32_t>(swath_raw_bytes(s.header));
  s.data.assign(s.header.raw_bytes, static_cast<std::uint8_t>(i));
  return s;
}

// Sends `n` swaths in small chunks while `hook` mangles frames; returns what was printed.
std::vector<std::uint32_t> run(RxFaultHook hook, int n, LinkStats* stats = nullptr) {
  Counting sink;
  PrinterModel m;
  m.nozzles_per_ink = 16;
  PrinterController printer(m, &sink);
  printer.set_rx_fault_hook(std::move(hook));
  FirmwareTransport t(printer);
  LinkOptions o;
  o.chunk_bytes = 100;  // many frames per swath
  o.retransmit_timeout = milliseconds(50);
  HostLink link(t, o);
  EXPECT_TRUE(link.handshake());
  EXPECT_TRUE(link.send_msg(MessageType::kJobBegin, JobBeginMsg{1, "j", 0, 0}));
  for (int i = 0; i < n; ++i) EXPECT_TRUE(link.send_swath(raw_swath(static_cast<std::uint32_t>(i))));
  EXPECT_TRUE(link.send_msg(MessageType::kJobEnd, JobEndMsg{static_cast<std::uint32_t>(n), 0}));
  EXPECT_TRUE(link.drain(milliseconds(5000)));
  auto st = link.query_status(milliseconds(2000));
  EXPECT_TRUE(st);
  if (st) {
    EXPECT_EQ(st->last_outcome, JobOutcome::kCompleted);
  }
  if (stats) *stats = link.stats();
  return sink.printed;
}

std::vector<std::uint32_t> iota(int n) {
  std::vector<std::uint32_t> v;
  for (int i = 0; i < n; ++i) v.push_back(static_cast<std::uint32_t>(i));
  return v;
}

TEST(HostLink, DeliversEverythingOnACleanLink) {
  LinkStats s;
  EXPECT_EQ(run({}, 4, &s), iota(4));
  EXPECT_EQ(s.frames_resent, 0u);
}

TEST(HostLink, ResendsAfterACorruptFrame) {
  LinkStats s;
  auto hook = [](std::uint64_t n, const FrameHeader&) { return n == 9 ? RxFault::kCorrupt : RxFault::kNone; };
  EXPECT_EQ(run(hook, 4, &s), iota(4)) << "every swath exactly once, in order";
  EXPECT_GE(s.naks_seen, 1u);
  EXPECT_GT(s.frames_resent, 0u);
}

TEST(HostLink, ResendsAfterALostFrame) {
  LinkStats s;
  auto hook = [](std::uint64_t n, const FrameHeader&) { return n == 12 ? RxFault::kDrop : RxFault::kNone; };
  EXPECT_EQ(run(hook, 4, &s), iota(4));
  EXPECT_GT(s.frames_resent, 0u);
}

TEST(HostLink, RecoversWhenTheLastFrameIsLostByTimer) {
  // The job_end frame vanishes: no later frame reveals the gap, only the retransmit timer can.
  std::set<std::uint64_t> dropped;
  auto hook = [&](std::uint64_t, const FrameHeader& h) {
    if (h.type == MessageType::kJobEnd && dropped.insert(h.seq).second) return RxFault::kDrop;
    return RxFault::kNone;
  };
  LinkStats s;
  EXPECT_EQ(run(hook, 2, &s), iota(2));
  EXPECT_GE(s.timeouts, 1u);
}

TEST(HostLink, SurvivesABurstOfLosses) {
  auto hook = [](std::uint64_t n, const FrameHeader&) {
    return (n >= 20 && n < 26) ? (n % 2 ? RxFault::kDrop : RxFault::kCorrupt) : RxFault::kNone;
  };
  EXPECT_EQ(run(hook, 5), iota(5));
}

TEST(HostLink, ReportsADeadLink) {
  PrinterModel m;
  PrinterController printer(m, nullptr);
  FirmwareTransport t(printer);
  LinkOptions o;
  o.retransmit_timeout = milliseconds(20);
  o.dead_link_timeout = milliseconds(200);
  HostLink link(t, o);
  ASSERT_TRUE(link.handshake());
  printer.set_rx_fault_hook([](std::uint64_t, const FrameHeader&) { return RxFault::kDrop; });
  ASSERT_TRUE(link.send(MessageType::kStatusQuery, {}));
  auto d = link.drain(milliseconds(3000));
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().code, ErrorCode::kTimeout);
  EXPECT_NE(d.error().message.find("acknowledged nothing"), std::string::npos) << d.error().message;
}

TEST(HostLink, HandshakeTimesOutOnASilentPrinter) {
  PrinterModel m;
  PrinterController printer(m, nullptr);
  printer.set_rx_fault_hook([](std::uint64_t, const FrameHeader&) { return RxFault::kDrop; });
  FirmwareTransport t(printer);
  LinkOptions o;
  o.handshake_timeout = milliseconds(50);
  o.handshake_attempts = 2;
  HostLink link(t, o);
  auto id = link.handshake();
  ASSERT_FALSE(id);
  EXPECT_EQ(id.error().code, ErrorCode::kTimeout);
  EXPECT_NE(id.error().message.find("did not answer hello (2 attempts"), std::string::npos) << id.error().message;
}

}  // namespace
}  // namespace tp::device
