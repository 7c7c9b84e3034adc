// tests/fuzz/host_hot_folder_fuzz.cpp: a hot-folder entry of any name (bytes that are not UTF-8
// included) and any contents is scanned and checked without crashing, and every refusal is text
// that can go into JSON. Input: the entry's name up to the first newline, then its contents; a
// name ending in '/' makes a folder whose job.json holds the contents, else a .zip file.
// fuzz-sources: host/daemon/hot_folder.cpp host/daemon/intake.cpp host/job host/common
// fuzz-sources: host/session/sim_reexec.cpp geometry/sewing/cloth_material.cpp geometry/samples/sizes.cpp
// fuzz-sources: geometry/body/measurements.cpp
// fuzz-sources: rip/colour/tone_curve.cpp rip/common/error.cpp
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "host/common/text.h"
#include "host/daemon/hot_folder.h"
#include "host/daemon/intake.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  using namespace tp::host;
  static const fs::path base = fs::temp_directory_path() / ("tp-hot-fuzz-" + std::to_string(::getpid()));
  std::error_code ec;
  fs::remove_all(base, ec);
  fs::create_directories(base / "hot");
  fs::create_directories(base / "scratch");

  const std::string input(reinterpret_cast<const char*>(data), size);
  const size_t nl = input.find('\n');
  std::string name = input.substr(0, std::min<size_t>(nl, 64));
  const std::string contents = nl == std::string::npos ? std::string() : input.substr(nl + 1);
  const bool folder = !name.empty() && name.back() == '/';
  for (char& c : name)
    if (c == '/' || c == '\0') c = '_';
  if (name.empty() || name == "." || name == ".." || name[0] == '.') name = "x" + name;
  const fs::path entry = base / "hot" / (folder ? name : name + ".zip");
  if (folder) {
    fs::create_directories(entry);
    std::ofstream(entry / "job.json", std::ios::binary) << contents;
  } else {
    std::ofstream(entry, std::ios::binary) << contents;
  }

  HotFolder hot(base / "hot", std::chrono::milliseconds(0));
  if (!hot.prepare()) __builtin_trap();
  (void)hot.scan();
  for (const fs::path& p : hot.scan()) {
    PackageLimits limits;
    limits.max_total_bytes = 8u << 20;
    limits.max_entry_bytes = 4u << 20;
    auto checked = check_package(p, base / "scratch", limits);
    if (!checked) (void)dump_json(nlohmann::json{{"error", checked.error().message}, {"entry", p.filename().string()}});
  }
  return 0;
}
