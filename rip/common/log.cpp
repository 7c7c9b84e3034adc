// rip/common/log.cpp: creates the rip layer's logger once, shared by every rip source file.
#include <spdlog/sinks/stdout_color_sinks.h>

#include "rip/common/internal/log.h"

namespace tp::rip {

spdlog::logger& logger() {
  // A function-local static gives thread-safe one-time creation; reuse a registered "rip"
  // logger if the host registered its own sinks under that name first.
  static std::shared_ptr<spdlog::logger> instance = [] {
    if (auto existing = spdlog::get("rip")) return existing;
    return spdlog::stderr_color_mt("rip");
  }();
  return *instance;
}

}  // namespace tp::rip
