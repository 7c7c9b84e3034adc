// tests/rip/swath/packbits_test.cpp: PackBits round trips, size bounds, the TIFF reference example and
// corrupt streams.
#include "rip/swath/packbits.h"

#include <random>

#include <gtest/gtest.h>

namespace tp::rip {
namespace {

std::vector<std::uint8_t> encode(const std::vector<std::uint8_t>& in) {
  std::vector<std::uint8_t> out;
  packbits_append(in, out);
  return out;
}

TEST(PackBits, DecodesTheTiffSpecificationExample) {
  // TIFF 6.0, section 9: the example stream and what it unpacks to.
  const std::vector<std::uint8_t> packed = {0xFE, 0xAA, 0x02, 0x80, 0x00, 0x2A, 0xFD, 0xAA, 0x03, 0x80, 0x00,
                                            0x2A, 0x22, 0xF7, 0xAA};
  const std::vector<std::uint8_t> want = {0xAA, 0xAA, 0xAA, 0x80, 0x00, 0x2A, 0xAA, 0xAA, 0xAA, 0xAA, 0x80, 0x00,
                                          0x2A, 0x22, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA};
  auto got = packbits_decode(packed, want.size());
  ASSERT_TRUE(got) << got.error().what();
  EXPECT_EQ(*got, want);
  EXPECT_EQ(encode(want).size(), packed.size());
}

TEST(PackBits, RoundTripsAndStaysWithinBound) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint8_t> in(rng() % 2000);
    const int style = trial % 3;
    for (auto& b : in) {
      if (style == 0) b = static_cast<std::uint8_t>(rng());
      else if (style == 1) b = static_cast<std::uint8_t>(rng() % 3 == 0 ? rng() % 4 : 0);
      else b = static_cast<std::uint8_t>((&b - in.data()) / 37 % 3);
    }
    auto enc = encode(in);
    EXPECT_LE(enc.size(), packbits_max_size(in.size()));
    auto dec = packbits_decode(enc, in.size());
    ASSERT_TRUE(dec) << dec.error().what();
    EXPECT_EQ(*dec, in) << "trial " << trial;
  }
}

TEST(PackBits, BlankRowsShrinkByFarMoreThan60x) {
  std::vector<std::uint8_t> blank(9449, 0);
  EXPECT_LE(encode(blank).size(), 2 * (9449 / 128 + 1));
}

TEST(PackBits, CorruptStreamsAreRejected) {
  auto truncated = packbits_decode(std::vector<std::uint8_t>{0x05, 1, 2}, 6);
  ASSERT_FALSE(truncated);
  EXPECT_NE(truncated.error().message.find("past the end"), std::string::npos);
  EXPECT_FALSE(packbits_decode(std::vector<std::uint8_t>{0xFE}, 3));                // run without its byte
  EXPECT_FALSE(packbits_decode(std::vector<std::uint8_t>{0xF0, 7}, 3));             // run overflows
  EXPECT_FALSE(packbits_decode(std::vector<std::uint8_t>{0x00, 7}, 2));             // too short
  auto noop = packbits_decode(std::vector<std::uint8_t>{0x80, 0x00, 9}, 1);         // -128 is a no-op
  ASSERT_TRUE(noop);
  EXPECT_EQ((*noop)[0], 9);
}

}  // namespace
}  // namespace tp::rip
