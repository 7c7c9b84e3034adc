// device/protocol/crc.cpp: table-driven CRC-16/CCITT and slicing-by-8 CRC-32.
#include "device/protocol/crc.h"

#include <array>

namespace tp::device {

namespace {

constexpr std::array<std::uint16_t, 256> make_crc16_table() {
  std::array<std::uint16_t, 256> t{};
  for (unsigned i = 0; i < 256; ++i) {
    std::uint16_t c = static_cast<std::uint16_t>(i << 8);
    for (int b = 0; b < 8; ++b) c = (c & 0x8000) ? static_cast<std::uint16_t>((c << 1) ^ 0x1021) : static_cast<std::uint16_t>(c << 1);
    t[i] = c;
  }
  return t;
}

// Eight tables so the payload CRC runs a word at a time: swath data is the bulk of the link's
// traffic and both ends checksum every byte (budget: well above the 53 MB/s USB 2.0 ceiling).
using Crc32Tables = std::array<std::array<std::uint32_t, 256>, 8>;

constexpr Crc32Tables make_crc32_tables() {
  Crc32Tables t{};
  for (unsigned i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int b = 0; b < 8; ++b) c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : (c >> 1);
    t[0][i] = c;
  }
  for (unsigned i = 0; i < 256; ++i)
    for (unsigned k = 1; k < 8; ++k) t[k][i] = (t[k - 1][i] >> 8) ^ t[0][t[k - 1][i] & 0xFF];
  return t;
}

constexpr auto kCrc16 = make_crc16_table();
constexpr auto kCrc32 = make_crc32_tables();

}  // namespace

std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes) {
  std::uint16_t crc = 0xFFFF;
  for (std::uint8_t b : bytes) crc = static_cast<std::uint16_t>((crc << 8) ^ kCrc16[((crc >> 8) ^ b) & 0xFF]);
  return crc;
}

std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::uint8_t> bytes) {
  std::uint32_t c = ~crc;
  const std::uint8_t* p = bytes.data();
  std::size_t n = bytes.size();
  while (n >= 8) {
    // Little-endian word assembly keeps this independent of host byte order.
    std::uint32_t lo = c ^ (std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
                            std::uint32_t(p[3]) << 24);
    std::uint32_t hi = std::uint32_t(p[4]) | std::uint32_t(p[5]) << 8 | std::uint32_t(p[6]) << 16 |
                       std::uint32_t(p[7]) << 24;
    c = kCrc32[7][lo & 0xFF] ^ kCrc32[6][(lo >> 8) & 0xFF] ^ kCrc32[5][(lo >> 16) & 0xFF] ^
        kCrc32[4][lo >> 24] ^ kCrc32[3][hi & 0xFF] ^ kCrc32[2][(hi >> 8) & 0xFF] ^
        kCrc32[1][(hi >> 16) & 0xFF] ^ kCrc32[0][hi >> 24];
    p += 8;
    n -= 8;
  }
  while (n--) c = (c >> 8) ^ kCrc32[0][(c ^ *p++) & 0xFF];
  return ~c;
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes) { return crc32_update(0, bytes); }

}  // namespace tp::device
