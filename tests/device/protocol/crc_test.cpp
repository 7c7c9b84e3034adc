// tests/device/protocol/crc_test.cpp: the link's checksums against their published check values.
#include "device/protocol/crc.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace tp::device {
namespace {

std::span<const std::uint8_t> bytes(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

TEST(Crc, MatchesPublishedCheckValues) {
  EXPECT_EQ(crc16_ccitt(bytes("123456789")), 0x29B1);
  EXPECT_EQ(crc32(bytes("123456789")), 0xCBF43926u);
  EXPECT_EQ(crc32({}), 0u);
}

TEST(Crc, RunningCrcEqualsOneShotAtEverySplit) {
  std::vector<std::uint8_t> data(1000);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 37 + 11);
  const std::uint32_t whole = crc32(data);
  for (std::size_t cut : {0u, 1u, 7u, 8u, 9u, 500u, 999u, 1000u}) {
    std::uint32_t c = crc32_update(0, std::span(data).first(cut));
    c = crc32_update(c, std::span(data).subspan(cut));
    EXPECT_EQ(c, whole) << "split at " << cut;
  }
}

TEST(Crc, DetectsEverySingleBitFlip) {
  std::vector<std::uint8_t> data(64, 0x5A);
  const std::uint32_t good = crc32(data);
  for (std::size_t bit = 0; bit < data.size() * 8; ++bit) {
    data[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    EXPECT_NE(crc32(data), good) << "bit " << bit;
    data[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
  }
}

}  // namespace
}  // namespace tp::device
