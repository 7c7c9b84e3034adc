// device/swath/swath.h: a swath: the drops one carriage pass lays, as the RIP makes it and the
// printer link carries it.
#pragma once

#include <cstdint>
#include <vector>

namespace tp::device {

enum class CarriageDirection : std::uint8_t { kLeftToRight = 0, kRightToLeft = 1 };
enum class SwathCompression : std::uint8_t { kNone = 0, kPackBits = 1 };

/// Where a swath lands and how its data is laid out.
///
/// Data is channel-major: for each ink channel, `rows` rows of `width_px` pixels packed at
/// `bits_per_pixel` (MSB first, rows padded to whole bytes). Row r of the swath prints on
/// fabric row `first_row + r * row_step`; pixel c of a row on fabric column `x_start_px + c`.
struct SwathHeader {
  std::uint32_t index = 0;            ///< 0-based, consecutive within a job
  std::uint16_t pass = 0;             ///< pass number within a multi-pass band
  CarriageDirection direction = CarriageDirection::kLeftToRight;
  std::int64_t first_row = 0;         ///< fabric row (at dpi_y) of swath row 0
  std::uint16_t row_step = 1;         ///< fabric rows between consecutive swath rows
  std::uint32_t rows = 0;
  std::int32_t x_start_px = 0;
  std::uint32_t width_px = 0;
  std::uint8_t channels = 4;
  std::uint8_t bits_per_pixel = 2;
  std::uint32_t feed_before_um = 0;   ///< fabric advance before this swath prints
  SwathCompression compression = SwathCompression::kNone;
  std::uint32_t raw_bytes = 0;        ///< uncompressed data size
};

struct Swath {
  SwathHeader header;
  std::vector<std::uint8_t> data;     ///< compressed per `header.compression`
};

/// Bytes in one uncompressed row of one channel.
inline std::uint32_t swath_row_bytes(const SwathHeader& h) {
  return (h.width_px * h.bits_per_pixel + 7) / 8;
}

/// Bytes of a whole uncompressed swath: every channel's rows (what `raw_bytes` must say).
inline std::uint64_t swath_raw_bytes(const SwathHeader& h) {
  return std::uint64_t(swath_row_bytes(h)) * h.rows * h.channels;
}

}  // namespace tp::device
