// device/swath/packbits.h: PackBits run-length coding of swath data (TIFF compression 32773,
// Apple TN1023): the one codec the RIP encodes with and the firmware and the simulator decode.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "device/common/error.h"

namespace tp::device {

/// Worst-case encoded size of `n` bytes: one header byte per (started) 128 literal bytes.
inline constexpr std::size_t packbits_max_size(std::size_t n) { return n + (n + 127) / 128; }

/// Encodes `raw` into `out`, which holds at least packbits_max_size(raw.size()) bytes, and
/// returns the encoded size. Header n in 0..127: n+1 literal bytes follow; n in -127..-1: the next
/// byte repeats 1-n times. Runs of 3+ equal bytes become repeat packets; runs of two stay inside
/// literals (same size, and a literal header would follow anyway).
std::size_t packbits_encode(std::span<const std::uint8_t> raw, std::uint8_t* out);

/// Appends the PackBits encoding of `raw` to `out`.
void packbits_encode(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out);

/// Decodes PackBits `packed` into exactly `expected_bytes` bytes appended to `out`. Fails with
/// kInvalidArgument if the stream ends inside a packet or decodes to a different size (the
/// message says at which input offset). Header -128 is a no-op, as the TIFF specification says.
[[nodiscard]] Status packbits_decode(std::span<const std::uint8_t> packed, std::size_t expected_bytes,
                                     std::vector<std::uint8_t>& out);

}  // namespace tp::device
