// tests/device/swath/packbits_test.cpp: PackBits as the firmware decodes it: golden bytes,
// round trips over awkward runs, and refusal of broken streams.
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
    EXPECT_LE(packed.size(), raw.size() + raw.size() / 128 + 1);
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

}  // namespace
}  // namespace tp::device
