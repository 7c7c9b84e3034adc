// device/swath/packbits.cpp: PackBits encoder tuned for screened rows (long blank runs, short
// literals) and the bounds-checked decoder.
#include "device/swath/packbits.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>

namespace tp::device {

namespace {

/// Length of the run of bytes equal to in[i] starting at i, capped at 128.
inline std::size_t run_length(const std::uint8_t* in, std::size_t i, std::size_t n) {
  const std::size_t end = std::min(n, i + 128);
  const std::uint8_t b = in[i];
  std::size_t j = i + 1;
  // Compare eight bytes at a time: blank fabric gives long zero runs.
  const std::uint64_t pattern = 0x0101010101010101ull * b;
  while (j + 8 <= end) {
    std::uint64_t w;
    std::memcpy(&w, in + j, 8);
    if (w != pattern) break;
    j += 8;
  }
  while (j < end && in[j] == b) ++j;
  return j - i;
}

/// First index j in [i, end) that starts a run of three equal bytes, or `end`. Eight positions are
/// tested per step: byte k of (w ^ w1) | (w ^ w2) is zero exactly where bytes k, k+1, k+2 match
/// (little-endian loads, so the lowest zero byte is the first position).
inline std::size_t next_triple(const std::uint8_t* in, std::size_t i, std::size_t end) {
  constexpr std::uint64_t kLow = 0x0101010101010101ull, kHigh = 0x8080808080808080ull;
  while (i + 10 <= end) {
    std::uint64_t w, w1, w2;
    std::memcpy(&w, in + i, 8);
    std::memcpy(&w1, in + i + 1, 8);
    std::memcpy(&w2, in + i + 2, 8);
    const std::uint64_t d = (w ^ w1) | (w ^ w2);
    const std::uint64_t zero = (d - kLow) & ~d & kHigh;  // high bit set in (at least the first) zero byte
    if (zero) return i + static_cast<std::size_t>(std::countr_zero(zero) / 8);
    i += 8;
  }
  for (; i + 2 < end; ++i)
    if (in[i] == in[i + 1] && in[i] == in[i + 2]) return i;
  return end;
}

}  // namespace

std::size_t packbits_encode(std::span<const std::uint8_t> raw, std::uint8_t* out) {
  const std::uint8_t* in = raw.data();
  const std::size_t n = raw.size();
  std::size_t i = 0, o = 0;
  while (i < n) {
    // Literal stretch up to the next run of three, in packets of at most 128 bytes.
    const std::size_t run_at = next_triple(in, i, n);
    while (i < run_at) {
      const std::size_t k = std::min<std::size_t>(run_at - i, 128);
      out[o++] = static_cast<std::uint8_t>(k - 1);
      std::memcpy(out + o, in + i, k);
      o += k;
      i += k;
    }
    if (i >= n) break;
    const std::size_t run = run_length(in, i, n);
    out[o++] = static_cast<std::uint8_t>(1 - static_cast<int>(run));
    out[o++] = in[i];
    i += run;
  }
  return o;
}

void packbits_encode(std::span<const std::uint8_t> raw, std::vector<std::uint8_t>& out) {
  const std::size_t at = out.size();
  out.resize(at + packbits_max_size(raw.size()));
  out.resize(at + packbits_encode(raw, out.data() + at));
}

Status packbits_decode(std::span<const std::uint8_t> packed, std::size_t expected_bytes,
                       std::vector<std::uint8_t>& out) {
  const std::size_t base = out.size();
  out.reserve(base + expected_bytes);
  std::size_t i = 0;
  auto too_long = [&](std::size_t at) {
    return fail(ErrorCode::kInvalidArgument, "packbits: decodes past the expected " + std::to_string(expected_bytes) +
                                                 " bytes at input offset " + std::to_string(at));
  };
  while (i < packed.size()) {
    const auto h = static_cast<std::int8_t>(packed[i]);
    const std::size_t at = i++;
    if (h >= 0) {
      const std::size_t len = static_cast<std::size_t>(h) + 1;
      if (packed.size() - i < len)
        return fail(ErrorCode::kInvalidArgument,
                    "packbits: literal packet at input offset " + std::to_string(at) + " runs past the end");
      if (out.size() - base + len > expected_bytes) return too_long(at);
      out.insert(out.end(), packed.begin() + static_cast<long>(i), packed.begin() + static_cast<long>(i + len));
      i += len;
    } else if (h != -128) {
      const std::size_t len = static_cast<std::size_t>(1 - h);
      if (i >= packed.size())
        return fail(ErrorCode::kInvalidArgument,
                    "packbits: repeat packet at input offset " + std::to_string(at) + " lacks its byte");
      if (out.size() - base + len > expected_bytes) return too_long(at);
      out.insert(out.end(), len, packed[i++]);
    }
  }
  if (out.size() - base != expected_bytes)
    return fail(ErrorCode::kInvalidArgument, "packbits: decoded " + std::to_string(out.size() - base) +
                                                 " bytes, expected " + std::to_string(expected_bytes));
  return {};
}

}  // namespace tp::device
