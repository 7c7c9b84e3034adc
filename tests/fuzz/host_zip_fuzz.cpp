// tests/fuzz/host_zip_fuzz.cpp: zip unpacking never crashes and never writes outside its folder.
// fuzz-sources: host/job host/common host/session/sim_reexec.cpp geometry/sewing/cloth_material.cpp
// fuzz-sources: geometry/samples/sizes.cpp geometry/body/measurements.cpp
// fuzz-sources: rip/colour/tone_curve.cpp rip/common/error.cpp
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "host/job/package.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  static const fs::path base = fs::temp_directory_path() / ("tp-zip-fuzz-" + std::to_string(::getpid()));
  fs::remove_all(base);
  fs::create_directories(base / "out");
  {
    std::ofstream(base / "in.zip", std::ios::binary).write(reinterpret_cast<const char*>(data),
                                                           static_cast<std::streamsize>(size));
  }
  tp::host::PackageLimits limits;
  limits.max_total_bytes = 8u << 20;
  limits.max_entry_bytes = 4u << 20;
  (void)tp::host::unpack_zip(base / "in.zip", base / "out", limits);
  // Nothing may appear beside the output folder except the input itself.
  for (const auto& e : fs::directory_iterator(base))
    if (e.path().filename() != "in.zip" && e.path().filename() != "out") __builtin_trap();
  return 0;
}
