// tests/device/swath/packbits_test.cpp: the one PackBits codec (RIP, firmware, simulator): golden
// bytes, round trips within the worst-case size, and refusal of broken streams.
#include "device/swath/packbits.h"

#include <gtest/gtest.h>

#include <random>

namespace tp::device {
namespace {

TEST(PackBits, DecodesTheClassicExampleFromAppleTN1023) {
  // The packed stream of Apple's Technical Note TN1023, which every PackBits reader must accept.
  const std::vector<std::uint8_t> packed = {0xFE, 0xAA, 0x02, 0x80, 0x00, 0x2A, 0xFD, 0xAA, 0x03, 0x80, 0x00,
                                            0x2A, 0x22, 0xF7, 0xAA};
  std::vector<std::uint8_t> out;
  ASSERT_TRUE(packbits_decode(packed, 24, out));
  const std::vector<std::uint8_t> want = {0xAA, 0xAA, 0xAA, 0x80, 0x00, 0x2A, 0xAA, 0xAA, 0xAA, 0xAA, 0x80, 0x00,
                                          0x2A, 0x22, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA};
  EXPECT_EQ(out, want);
}

TEST(PackBits, EncodesRunsAndLiteralsToGoldenBytes) {
  std::vector<std::uint8_t> raw = {1, 2, 3, 9, 9, 9, 9, 4};
  std::vector<std::uint8_t> packed;
  packbits_encode(raw, packed);
  EXPECT_EQ(packed, (std::vector<std::uint8_t>{0x02, 1, 2, 3, 0xFD, 9, 0x00, 4}));
}

TEST(PackBits, RoundTripsRandomAndRunHeavyData) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint8_t> raw(rng() % 2000);
    for (std::size_t i = 0; i < raw.size(); ++i)
      raw[i] = (trial % 3 == 0) ? static_cast<std::uint8_t>(rng()) : static_cast<std::uint8_t>((i / (1 + trial % 150)) % 3);
    std::vector<std::uint8_t> packed, back;
    packbits_encode(raw, packed);
    EXPECT_LE(packed.size(), packbits_max_size(raw.size()));
    ASSERT_TRUE(packbits_decode(packed, raw.size(), back));
    ASSERT_EQ(back, raw) << "trial " << trial;
  }
}

TEST(PackBits, RefusesBrokenStreams) {
  std::vector<std::uint8_t> out;
  auto s = packbits_decode(std::vector<std::uint8_t>{0x05, 1, 2}, 6, out);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("literal packet at input offset 0 runs past the end"), std::string::npos);
  out.clear();
  s = packbits_decode(std::vector<std::uint8_t>{0xF0}, 17, out);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("lacks its byte"), std::string::npos);
  out.clear();
  s = packbits_decode(std::vector<std::uint8_t>{0x81, 7}, 10, out);  // 128 bytes into a 10-byte swath
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("past the expected 10 bytes"), std::string::npos);
  out.clear();
  s = packbits_decode(std::vector<std::uint8_t>{0x00, 7}, 2, out);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("decoded 1 bytes, expected 2"), std::string::npos);
}

TEST(PackBits, ReencodesTheTiffExampleToItsOwnSize) {
  // TIFF 6.0, section 9: the same 24 bytes encode to as few bytes as the specification's stream.
  const std::vector<std::uint8_t> raw = {0xAA, 0xAA, 0xAA, 0x80, 0x00, 0x2A, 0xAA, 0xAA, 0xAA, 0xAA, 0x80, 0x00,
                                         0x2A, 0x22, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA};
  std::vector<std::uint8_t> packed;
  packbits_encode(raw, packed);
  EXPECT_EQ(packed.size(), 15u);
}

TEST(PackBits, FixedBufferAndAppendingEncodersAgreeAndMeetTheWorstCase) {
  std::mt19937 rng(11);
  for (std::size_t n : {0u, 1u, 2u, 127u, 128u, 129u, 1000u, 4097u}) {
    std::vector<std::uint8_t> raw(n);
    for (auto& b : raw) b = static_cast<std::uint8_t>(rng());  // incompressible: the worst case
    std::vector<std::uint8_t> fixed(packbits_max_size(n));
    fixed.resize(packbits_encode(raw, fixed.data()));
    std::vector<std::uint8_t> appended = {0x5A};
    packbits_encode(raw, appended);
    EXPECT_EQ(std::vector<std::uint8_t>(appended.begin() + 1, appended.end()), fixed) << n << " bytes";
    EXPECT_LE(fixed.size(), packbits_max_size(n));
  }
}

TEST(PackBits, BlankRowsShrinkByFarMoreThan60x) {
  std::vector<std::uint8_t> blank(9449, 0), packed;
  packbits_encode(blank, packed);
  EXPECT_LE(packed.size(), 2 * (9449 / 128 + 1));
}

TEST(PackBits, HeaderMinus128IsANoOp) {
  std::vector<std::uint8_t> out;
  ASSERT_TRUE(packbits_decode(std::vector<std::uint8_t>{0x80, 0x00, 9}, 1, out));
  EXPECT_EQ(out, std::vector<std::uint8_t>{9});
}

}  // namespace
}  // namespace tp::device
