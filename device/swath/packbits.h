// device/swath/packbits.h: PackBits run-length coding of swath data (TIFF/Apple PackBits), the
// compression the printer decodes in firmware.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "device/common/error.h"

namespace tp::device {

/// Appends the PackBits encoding of `raw` to `out`. Runs of 3+ equal bytes become repeat
/// packets; everything else literal packets of up to 128 bytes. Worst case grows the data by
/// one byte per 128.
void packbits_encode(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out);

/// Decodes PackBits `packed` into exactly `expected_bytes` bytes appended to `out`. Fails with
/// kInvalidArgument if the stream ends inside a packet or decodes to a different size (the
/// message says at which input offset).
Status packbits_decode(std::span<const std::uint8_t> packed, std::size_t expected_bytes,
                       std::vector<std::uint8_t>& out);

}  // namespace tp::device
