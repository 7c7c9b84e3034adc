// tests/device/protocol/messages_test.cpp: every message survives encode/decode; broken payloads
// fail with the message and field named.
#include "device/protocol/messages.h"

#include <gtest/gtest.h>

namespace tp::device {
namespace {

template <class M, class Decode>
M round_trip(const M& m, Decode decode) {
  std::vector<std::uint8_t> p;
  encode(m, p);
  auto r = decode(p);
  EXPECT_TRUE(r) << (r ? "" : r.error().message);
  return r ? *r : M{};
}

TEST(Messages, HelloAndIdentifyRoundTrip) {
  HelloMsg h{1, 3, 65536, "cutroom-box"};
  auto h2 = round_trip(h, decode_hello);
  EXPECT_EQ(h2.max_version, 3);
  EXPECT_EQ(h2.host, "cutroom-box");

  IdentifyMsg id;
  id.model = "TP-X";
  id.ieee1284_id = "MFG:A;MDL:B;";
  id.firmware = "fw 2";
  id.dpi_x = 720;
  id.dpi_y = 1440;
  id.inks = {"cyan", "magenta", "yellow", "black", "light_cyan"};
  id.swath_slots = 12;
  id.swath_buffer_bytes = 1u << 26;
  id.print_width_um = 1850000;
  auto id2 = round_trip(id, decode_identify);
  EXPECT_EQ(id2.inks, id.inks);
  EXPECT_EQ(id2.dpi_y, 1440);
  EXPECT_EQ(id2.print_width_um, 1850000u);
}

TEST(Messages, SwathHeaderRoundTripsEveryField) {
  SwathHeaderMsg m;
  m.header.index = 77;
  m.header.pass = 3;
  m.header.direction = CarriageDirection::kRightToLeft;
  m.header.first_row = -12;
  m.header.row_step = 4;
  m.header.rows = 320;
  m.header.x_start_px = 17;
  m.header.width_px = 9000;
  m.header.channels = 6;
  m.header.bits_per_pixel = 2;
  m.header.feed_before_um = 13547;
  m.header.compression = SwathCompression::kPackBits;
  m.header.raw_bytes = 123456;
  m.data_bytes = 99999;
  m.data_crc32 = 0xDEADBEEF;
  auto r = round_trip(m, decode_swath_header);
  EXPECT_EQ(r.header.first_row, -12);
  EXPECT_EQ(r.header.direction, CarriageDirection::kRightToLeft);
  EXPECT_EQ(r.header.compression, SwathCompression::kPackBits);
  EXPECT_EQ(r.header.feed_before_um, 13547u);
  EXPECT_EQ(r.data_crc32, 0xDEADBEEFu);
}

TEST(Messages, StatusAndReportRoundTrip) {
  StatusMsg s;
  s.ack_seq = 900;
  s.naks = 2;
  s.state = PrinterState::kWaitingForCue;
  s.condition = PrinterCondition::kCoverOpen;
  s.job_id = 1ull << 40;
  s.swath_next = 30;
  s.printed_next = 25;
  s.free_slots = 3;
  s.fabric_pos_um = 1234567;
  s.cue_waiting = 4;
  s.last_outcome = JobOutcome::kAborted;
  auto s2 = round_trip(s, decode_status);
  EXPECT_EQ(s2.state, PrinterState::kWaitingForCue);
  EXPECT_EQ(s2.condition, PrinterCondition::kCoverOpen);
  EXPECT_EQ(s2.job_id, 1ull << 40);
  EXPECT_EQ(s2.cue_waiting, 4u);
  EXPECT_EQ(s2.last_outcome, JobOutcome::kAborted);

  JobReportMsg r;
  r.job_id = 5;
  r.name = "shirt";
  r.outcome = JobOutcome::kCompleted;
  r.drops_per_ink = {1, 2, 3, 4};
  r.print_time_us = 987654321;
  auto r2 = round_trip(r, decode_job_report);
  EXPECT_EQ(r2.drops_per_ink, r.drops_per_ink);
  EXPECT_EQ(r2.print_time_us, 987654321u);
  EXPECT_EQ(r2.name, "shirt");
}

TEST(Messages, SwathDataViewsItsPayload) {
  std::vector<std::uint8_t> chunk{1, 2, 3, 4, 5};
  SwathDataMsg m{9, 4096, chunk};
  std::vector<std::uint8_t> p;
  encode(m, p);
  auto r = decode_swath_data(p);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->offset, 4096u);
  ASSERT_EQ(r->data.size(), 5u);
  EXPECT_EQ(r->data.data(), p.data() + kSwathDataOverheadBytes);
}

TEST(Messages, TruncatedPayloadNamesMessageAndField) {
  std::vector<std::uint8_t> p;
  encode(SwathHeaderMsg{}, p);
  p.resize(27);  // cut inside width_px (bytes 25..28)
  auto r = decode_swath_header(p);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kMalformedFrame);
  EXPECT_NE(r.error().message.find("swath_header"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("'width_px'"), std::string::npos) << r.error().message;
}

TEST(Messages, TrailingBytesAreRejected) {
  std::vector<std::uint8_t> p;
  encode(FeedMsg{10}, p);
  p.push_back(0);
  auto r = decode_feed(p);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("trailing"), std::string::npos);
}

TEST(Messages, EnumsOutOfRangeAreRejected) {
  std::vector<std::uint8_t> p;
  encode(StatusMsg{}, p);
  p[8] = 42;  // state
  auto r = decode_status(p);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("state 42"), std::string::npos) << r.error().message;

  std::vector<std::uint8_t> c;
  encode(CutterCueMsg{1, CueKind::kCut, 5, 0}, c);
  c[4] = 9;  // kind
  auto rc = decode_cutter_cue(c);
  ASSERT_FALSE(rc);
  EXPECT_NE(rc.error().message.find("kind 9"), std::string::npos);

  std::vector<std::uint8_t> z;
  encode(CutterCueMsg{0, CueKind::kCut, 5, 0}, z);
  EXPECT_FALSE(decode_cutter_cue(z));
}

TEST(Messages, HelloWithInvertedVersionRangeIsRejected) {
  std::vector<std::uint8_t> p;
  encode(HelloMsg{4, 2, 1024, "x"}, p);
  auto r = decode_hello(p);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("min_version 4"), std::string::npos);
}

TEST(Messages, IdentifyWithTooManyInksIsRejectedBeforeAllocating) {
  std::vector<std::uint8_t> p;
  IdentifyMsg id;
  id.inks.assign(3, "k");
  encode(id, p);
  // Find the ink count byte: after the fixed fields and three strings; set it to 200.
  const std::size_t at = 2 + 2 + 2 + 2 + 2 + 2 + 4 + 4 + 4 + 2 + 1;
  ASSERT_EQ(p[at], 3);
  p[at] = 200;
  auto r = decode_identify(p);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("200 inks"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace tp::device
