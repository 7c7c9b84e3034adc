// tests/fuzz/host_manifest_fuzz.cpp: job.json validation never crashes on any input.
// fuzz-sources: host/job host/common host/session/sim_reexec.cpp geometry/sewing/cloth_material.cpp
// fuzz-sources: geometry/samples/sizes.cpp geometry/body/measurements.cpp
// fuzz-sources: rip/colour/tone_curve.cpp rip/common/error.cpp
#include <cstddef>
#include <cstdint>
#include <string>

#include "host/job/manifest.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  auto job = tp::host::parse_job(text, nullptr);
  // A failure must say where: every line names job.json.
  if (!job && job.error().message.rfind("job.json", 0) != 0) __builtin_trap();
  return 0;
}
