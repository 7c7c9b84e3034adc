// rip/screen/threshold_screen.cpp: the blue-noise threshold screen's hot loop (one row, 128-pixel blocks).
#include "rip/screen/internal/threshold_screen.h"

#include <cstring>

#include "rip/screen/blue_noise.h"

namespace tp::rip {

namespace {

constexpr int kN = kBlueNoiseSize;
constexpr int kBlock = 128;
static_assert(kN == kBlock, "rows are screened in blocks of one tile width");

/// Tile placement per channel: dihedral transform (0..7) and offset, chosen far apart on the torus.
struct Placement {
  int transform, dx, dy;
};
constexpr Placement kPlacements[] = {{0, 0, 0},    {5, 64, 37},  {3, 21, 93},  {6, 107, 59},
                                     {1, 43, 11},  {7, 86, 114}, {2, 13, 70},  {4, 99, 26}};

std::vector<std::uint16_t> placed_tile(int channel) {
  const Placement p = kPlacements[channel % 8];
  const int extra = channel / 8;  // more than 8 inks: shift further
  const auto& ranks = blue_noise_ranks();
  std::vector<std::uint16_t> t(static_cast<size_t>(kN) * kN);
  for (int y = 0; y < kN; ++y) {
    for (int x = 0; x < kN; ++x) {
      int sx = (x + p.dx + 17 * extra) % kN, sy = (y + p.dy + 29 * extra) % kN;
      int u = sx, v = sy;
      if (p.transform & 1) u = kN - 1 - u;
      if (p.transform & 2) v = kN - 1 - v;
      if (p.transform & 4) std::swap(u, v);
      // Ranks 0..16383 spread to thresholds 2..65534 (strictly inside (0, 65536)).
      t[static_cast<size_t>(y) * kN + x] = static_cast<std::uint16_t>(ranks[static_cast<size_t>(v) * kN + u] * 4 + 2);
    }
  }
  return t;
}

/// Four 2-bit codes (bytes 0..3 of w, little-endian) to one byte, first pixel in the top bits.
inline std::uint8_t pack4(std::uint32_t w) {
  // Multiplying spreads byte i to bit 36 - 10 i; the four fields meet at bits 30..37 without
  // carries because the stray cross products land on disjoint bits below 30 or above 37.
  const std::uint64_t m = (std::uint64_t{1} << 36) | (std::uint64_t{1} << 26) | (std::uint64_t{1} << 16) | (1u << 6);
  return static_cast<std::uint8_t>((w * m) >> 30);
}

}  // namespace

ThresholdScreen::ThresholdScreen(const ScreenSetup& setup) : setup_(setup) {
  multiplier_ = static_cast<std::uint32_t>((setup.levels - 1) * 65535 / 255);
  for (int l = 0; l < setup.levels; ++l) codes_[l] = drop_code(setup, l);
  for (int c = 0; c < setup.channels; ++c) tiles_.push_back(placed_tile(c));
}

void ThresholdScreen::screen_row(int channel, std::int64_t row, const std::uint8_t* contone, std::uint8_t* packed) {
  const std::uint16_t* trow = tiles_[channel].data() + static_cast<size_t>(row & (kN - 1)) * kN;
  const int width = setup_.width_px, bits = setup_.bits_per_pixel;
  const std::uint32_t mult = multiplier_;
  const bool identity_codes = setup_.levels == (1 << bits);
  alignas(64) std::uint8_t code[kBlock];
  for (int x0 = 0; x0 < width; x0 += kBlock) {
    const std::uint8_t* v = contone + x0;
    const int n = std::min(kBlock, width - x0);
    std::uint8_t* out = packed + x0 * bits / 8;
    const int out_bytes = (n * bits + 7) / 8;
    // Blank fabric is common between pieces: skip it eight pixels at a time.
    std::uint64_t any = 0;
    for (int i = 0; i < kBlock; i += 8) {
      std::uint64_t w;
      std::memcpy(&w, v + i, 8);
      any |= w;
    }
    if (any == 0) {
      std::memset(out, 0, static_cast<size_t>(out_bytes));
      continue;
    }
    for (int i = 0; i < kBlock; ++i) code[i] = static_cast<std::uint8_t>((v[i] * mult + trow[i]) >> 16);
    if (!identity_codes)
      for (int i = 0; i < kBlock; ++i) code[i] = codes_[code[i]];
    if (bits == 2) {
      std::uint8_t tmp[kBlock / 4];
      for (int j = 0; j < kBlock / 4; ++j) {
        std::uint32_t w;
        std::memcpy(&w, code + 4 * j, 4);
        tmp[j] = pack4(w);
      }
      std::memcpy(out, tmp, static_cast<size_t>(out_bytes));
    } else {
      std::uint8_t tmp[kBlock / 8];
      for (int j = 0; j < kBlock / 8; ++j) {
        std::uint8_t b = 0;
        for (int k = 0; k < 8; ++k) b = static_cast<std::uint8_t>((b << 1) | code[8 * j + k]);
        tmp[j] = b;
      }
      std::memcpy(out, tmp, static_cast<size_t>(out_bytes));
    }
    // The last block may cover padding: clear the pad bits of the final byte.
    if (n < kBlock && (n * bits) % 8 != 0) out[out_bytes - 1] &= static_cast<std::uint8_t>(0xff << (8 - (n * bits) % 8));
  }
}

}  // namespace tp::rip
