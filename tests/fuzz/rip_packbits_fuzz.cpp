// tests/fuzz/rip_packbits_fuzz.cpp: fuzzes the PackBits decoder (swath data from the wire) and checks
// the encoder round-trips whatever bytes arrive.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "rip/swath/packbits.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  // The first two bytes choose the expected decoded size; the rest is the stream.
  const std::size_t want = (static_cast<std::size_t>(data[0]) << 8 | data[1]) % 4096;
  const std::span<const std::uint8_t> body(data + 2, size - 2);
  auto decoded = tp::rip::packbits_decode(body, want);
  if (decoded && decoded->size() != want) std::abort();

  std::vector<std::uint8_t> enc(tp::rip::packbits_max_size(body.size()));
  enc.resize(tp::rip::packbits_encode(body, enc.data()));
  auto back = tp::rip::packbits_decode(enc, body.size());
  if (!back || !std::equal(back->begin(), back->end(), body.begin(), body.end())) std::abort();
  return 0;
}
