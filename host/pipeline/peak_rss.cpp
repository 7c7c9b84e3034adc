// host/pipeline/peak_rss.cpp: VmRSS / VmHWM of /proc/self/status and the peak's reset.
#include "host/pipeline/internal/peak_rss.h"

#include <fstream>
#include <string>

namespace tp::host::internal {

namespace {

std::optional<double> status_kib(const std::string& field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(field + ":", 0) != 0) continue;
    try {
      return std::stod(line.substr(field.size() + 1)) / 1024.0;
    } catch (...) {
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> resident_mib() { return status_kib("VmRSS"); }
std::optional<double> peak_resident_mib() { return status_kib("VmHWM"); }

bool reset_peak_resident() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

}  // namespace tp::host::internal
