// tests/device/protocol/frame_test.cpp: frame encoding (golden bytes) and the resynchronising
// decoder under split, corrupt and hostile input.
#include "device/protocol/frame.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "device/protocol/messages.h"

namespace tp::device {
namespace {

std::string hex(const std::vector<std::uint8_t>& v) {
  std::string s;
  char b[3];
  for (auto x : v) {
    std::snprintf(b, sizeof b, "%02x", x);
    s += b;
  }
  return s;
}

std::vector<std::uint8_t> frame(MessageType t, std::uint32_t seq, std::vector<std::uint8_t> payload) {
  std::vector<std::uint8_t> out;
  EXPECT_TRUE(encode_frame(t, seq, payload, out));
  return out;
}

TEST(Frame, FeedMessageEncodesToGoldenBytes) {
  // A feed of 54187 um as frame 7: magic "TP", version 1, type 0x14, seq, length 4, flags 0,
  // header CRC-16, payload, payload CRC-32. Any change here breaks printers in the field.
  std::vector<std::uint8_t> payload;
  encode(FeedMsg{54187}, payload);
  EXPECT_EQ(hex(frame(MessageType::kFeed, 7, payload)), "5450011407000000040000000000b7e8abd3000071cae134");
}

TEST(Frame, EmptyPayloadFrameIsTwentyBytes) {
  auto f = frame(MessageType::kStatusQuery, 1, {});
  EXPECT_EQ(f.size(), kFrameOverheadBytes);
}

TEST(Frame, RoundTripsWhenFedOneByteAtATime) {
  std::vector<std::uint8_t> stream;
  for (std::uint32_t seq = 1; seq <= 5; ++seq) {
    std::vector<std::uint8_t> payload(seq * 100);
    for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i ^ seq);
    auto f = frame(MessageType::kSwathData, seq, payload);
    stream.insert(stream.end(), f.begin(), f.end());
  }
  FrameDecoder d;
  std::vector<Frame> got;
  for (std::uint8_t b : stream) {
    d.feed(std::span(&b, 1));
    while (auto r = d.next()) {
      ASSERT_TRUE(*r) << r->error().message;
      got.push_back(std::move(**r));
    }
  }
  ASSERT_EQ(got.size(), 5u);
  for (std::uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(got[i].header.seq, i + 1);
    EXPECT_EQ(got[i].payload.size(), (i + 1) * 100u);
    EXPECT_EQ(got[i].payload[3], static_cast<std::uint8_t>(3 ^ (i + 1)));
  }
}

TEST(Frame, PayloadCorruptionIsReportedWithSequenceAndTypeThenSkipped) {
  auto a = frame(MessageType::kSwathData, 10, std::vector<std::uint8_t>(64, 1));
  auto b = frame(MessageType::kSwathData, 11, std::vector<std::uint8_t>(64, 2));
  a[30] ^= 0x04;
  FrameDecoder d;
  d.feed(a);
  d.feed(b);
  auto r1 = d.next();
  ASSERT_TRUE(r1 && !*r1);
  EXPECT_EQ(r1->error().code, ErrorCode::kCrcMismatch);
  EXPECT_NE(r1->error().message.find("seq 10"), std::string::npos) << r1->error().message;
  EXPECT_NE(r1->error().message.find("swath_data"), std::string::npos);
  auto r2 = d.next();
  ASSERT_TRUE(r2 && *r2);
  EXPECT_EQ((*r2)->header.seq, 11u);
  EXPECT_EQ(d.crc_errors(), 1u);
}

TEST(Frame, ResynchronisesAfterGarbageAndReportsTheLossOnce) {
  std::vector<std::uint8_t> stream = {0x00, 0x54, 0x50, 0x99, 0xFF, 0x54, 0x50, 0x01};  // junk, fake magics
  stream.insert(stream.end(), 40, 0xAB);
  auto good = frame(MessageType::kStatusQuery, 3, {});
  stream.insert(stream.end(), good.begin(), good.end());
  FrameDecoder d;
  d.feed(stream);
  int errors = 0;
  std::vector<std::uint32_t> seqs;
  while (auto r = d.next()) {
    if (*r) seqs.push_back((*r)->header.seq);
    else ++errors;
  }
  EXPECT_EQ(errors, 1);
  ASSERT_EQ(seqs.size(), 1u);
  EXPECT_EQ(seqs[0], 3u);
  EXPECT_EQ(d.bytes_skipped(), stream.size() - good.size());
}

TEST(Frame, HeaderAnnouncingAnOversizePayloadIsNotTrusted) {
  // A valid-looking header claiming 2 MiB must not make the decoder wait for 2 MiB.
  auto f = frame(MessageType::kSwathData, 1, std::vector<std::uint8_t>(16, 7));
  FrameDecoder small(8);
  small.feed(f);
  auto r = small.next();
  ASSERT_TRUE(r && !*r);
  EXPECT_EQ(r->error().code, ErrorCode::kMalformedFrame);
  EXPECT_FALSE(small.next().has_value());
}

TEST(Frame, RefusesToEncodeOversizePayload) {
  std::vector<std::uint8_t> big(kMaxFramePayloadBytes + 1), out;
  auto s = encode_frame(MessageType::kSwathData, 1, big, out);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidArgument);
  EXPECT_TRUE(out.empty());
}

TEST(Frame, TamperHookSeesPayloadAndTrailerBeforeTheCheck) {
  auto f = frame(MessageType::kCueDone, 4, {});
  FrameDecoder d;
  std::size_t seen = 0;
  d.set_tamper([&](const FrameHeader& h, std::span<std::uint8_t> bytes) {
    EXPECT_EQ(h.seq, 4u);
    seen = bytes.size();
    bytes[0] ^= 1;  // damage the CRC trailer of an empty payload
  });
  d.feed(f);
  auto r = d.next();
  EXPECT_EQ(seen, 4u);
  ASSERT_TRUE(r && !*r);
  EXPECT_EQ(r->error().code, ErrorCode::kCrcMismatch);
}

}  // namespace
}  // namespace tp::device
