// tests/fuzz/device_packbits_fuzz.cpp: fuzzes the PackBits decoder (swath data from the wire) and
// checks the encoder round-trips whatever bytes arrive.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "device/swath/packbits.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  // The first two bytes choose the expected decoded size; the rest is the stream.
  const std::size_t want = (static_cast<std::size_t>(data[0]) << 8 | data[1]) % 4096;
  const std::span<const std::uint8_t> body(data + 2, size - 2);
  std::vector<std::uint8_t> decoded;
  if (tp::device::packbits_decode(body, want, decoded) && decoded.size() != want) std::abort();

  std::vector<std::uint8_t> enc(tp::device::packbits_max_size(body.size()));
  enc.resize(tp::device::packbits_encode(body, enc.data()));
  std::vector<std::uint8_t> back;
  if (!tp::device::packbits_decode(enc, body.size(), back) ||
      !std::equal(back.begin(), back.end(), body.begin(), body.end()))
    std::abort();
  return 0;
}
