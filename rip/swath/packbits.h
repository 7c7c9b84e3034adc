// rip/swath/packbits.h: PackBits (TIFF compression 32773) run-length coding of swath rows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rip/common/error.h"

namespace tp::rip {

/// Worst-case encoded size of `n` bytes (one header byte per 128 literal bytes).
inline constexpr std::size_t packbits_max_size(std::size_t n) { return n + (n + 127) / 128; }

/// Encodes `in` (header n in 0..127: n+1 literal bytes follow; n in -127..-1: the next byte
/// repeats 1-n times) into `out`, which holds at least packbits_max_size(in.size()) bytes.
/// Returns the encoded size. Runs of two equal bytes inside literals stay literal (cheaper).
std::size_t packbits_encode(std::span<const std::uint8_t> in, std::uint8_t* out);

/// Appends the encoding of `in` to `out`.
void packbits_append(std::span<const std::uint8_t> in, std::vector<std::uint8_t>& out);

/// Decodes a PackBits stream that must expand to exactly `decoded_size` bytes.
/// Fails (kSwath) on a truncated stream, a run that overflows `decoded_size` or trailing data.
[[nodiscard]] Result<std::vector<std::uint8_t>> packbits_decode(std::span<const std::uint8_t> in,
                                                                std::size_t decoded_size);

}  // namespace tp::rip
