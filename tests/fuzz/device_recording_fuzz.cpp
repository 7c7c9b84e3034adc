// tests/fuzz/device_recording_fuzz.cpp: `printctl wire-dump` on arbitrary files: the recording
// reader and the dump must not crash, and a parsed recording's dump is deterministic.
#include <cstdint>
#include <cstdlib>

#include "device/protocol/describe.h"
#include "device/protocol/recording.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tp::device;
  auto recs = parse_recording(std::span(data, size), "fuzz.tpwire");
  if (!recs) return 0;
  if (dump_recording(*recs) != dump_recording(*recs)) std::abort();
  return 0;
}
