// tests/fuzz/device_frame_fuzz.cpp: the frame decoder and every message decoder on arbitrary
// bytes, fed in chunks whose sizes come from the input, as the printer's USB receive path sees
// them. Invariants: no crash, no unbounded buffering, every frame re-encodes to itself.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "device/protocol/describe.h"
#include "device/protocol/frame.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tp::device;
  if (size == 0) return 0;
  // First byte picks the chunk size, so frames straddle feed() calls in many ways.
  const std::size_t chunk = 1 + data[0] % 64;
  FrameDecoder dec(64 * 1024);
  for (std::size_t at = 1; at < size; at += chunk) {
    dec.feed(std::span(data + at, std::min(chunk, size - at)));
    while (auto r = dec.next()) {
      if (!*r) continue;
      const Frame& f = **r;
      (void)describe_frame(f);
      std::vector<std::uint8_t> again;
      if (!encode_frame(f.header.type, f.header.seq, f.payload, again, f.header.flags)) std::abort();
      FrameDecoder check;
      check.feed(again);
      auto back = check.next();
      if (!back || !*back || (*back)->payload != f.payload || (*back)->header.seq != f.header.seq) std::abort();
    }
    // A decoder never holds more than one maximal frame plus a chunk.
    if (dec.buffered_bytes() > 64 * 1024 + kFrameOverheadBytes + chunk) std::abort();
  }
  return 0;
}
