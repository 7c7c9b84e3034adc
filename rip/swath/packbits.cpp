// rip/swath/packbits.cpp: PackBits encoder tuned for screened rows (long blank runs, short literals).
#include "rip/swath/packbits.h"

#include <cstring>

#include <spdlog/fmt/fmt.h>

namespace tp::rip {

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
/// tested per step: byte k of (w ^ w1) | (w ^ w2) is zero exactly where bytes k, k+1, k+2 match.
inline std::size_t next_triple(const std::uint8_t* in, std::size_t i, std::size_t end) {
  constexpr std::uint64_t kLow = 0x0101010101010101ull, kHigh = 0x8080808080808080ull;
  while (i + 10 <= end) {
    std::uint64_t w, w1, w2;
    std::memcpy(&w, in + i, 8);
    std::memcpy(&w1, in + i + 1, 8);
    std::memcpy(&w2, in + i + 2, 8);
    const std::uint64_t d = (w ^ w1) | (w ^ w2);
    const std::uint64_t zero = (d - kLow) & ~d & kHigh;  // high bit set in (at least the first) zero byte
    if (zero) return i + static_cast<std::size_t>(__builtin_ctzll(zero) / 8);
    i += 8;
  }
  for (; i + 2 < end; ++i)
    if (in[i] == in[i + 1] && in[i] == in[i + 2]) return i;
  return end;
}

}  // namespace

std::size_t packbits_encode(std::span<const std::uint8_t> input, std::uint8_t* out) {
  const std::uint8_t* in = input.data();
  const std::size_t n = input.size();
  std::size_t i = 0, o = 0;
  while (i < n) {
    // Literal stretch up to the next run of three (runs of two stay literal: same size, and a
    // literal header would follow anyway).
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

void packbits_append(std::span<const std::uint8_t> in, std::vector<std::uint8_t>& out) {
  const std::size_t at = out.size();
  out.resize(at + packbits_max_size(in.size()));
  out.resize(at + packbits_encode(in, out.data() + at));
}

Result<std::vector<std::uint8_t>> packbits_decode(std::span<const std::uint8_t> in, std::size_t decoded_size) {
  std::vector<std::uint8_t> out;
  out.reserve(decoded_size);
  std::size_t i = 0;
  while (i < in.size()) {
    const auto h = static_cast<std::int8_t>(in[i++]);
    if (h >= 0) {
      const std::size_t k = static_cast<std::size_t>(h) + 1;
      if (i + k > in.size())
        return fail(ErrorCode::kSwath, fmt::format("packbits: literal of {} bytes at offset {} runs past the end of {} bytes",
                                                   k, i - 1, in.size()));
      if (out.size() + k > decoded_size)
        return fail(ErrorCode::kSwath, fmt::format("packbits: data at offset {} expands past {} bytes", i - 1, decoded_size));
      out.insert(out.end(), in.begin() + static_cast<std::ptrdiff_t>(i), in.begin() + static_cast<std::ptrdiff_t>(i + k));
      i += k;
    } else if (h != -128) {
      const std::size_t k = static_cast<std::size_t>(1 - h);
      if (i >= in.size())
        return fail(ErrorCode::kSwath, fmt::format("packbits: run at offset {} lacks its byte", i - 1));
      if (out.size() + k > decoded_size)
        return fail(ErrorCode::kSwath, fmt::format("packbits: data at offset {} expands past {} bytes", i - 1, decoded_size));
      out.insert(out.end(), k, in[i++]);
    }
  }
  if (out.size() != decoded_size)
    return fail(ErrorCode::kSwath, fmt::format("packbits: stream of {} bytes expands to {} bytes, expected {}",
                                               in.size(), out.size(), decoded_size));
  return out;
}

}  // namespace tp::rip
