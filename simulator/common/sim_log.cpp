// simulator/common/sim_log.cpp: the simulator's logger.
#include "simulator/internal/sim_log.h"

#include <spdlog/sinks/stdout_color_sinks.h>

#include <mutex>

namespace tp::sim {

std::shared_ptr<spdlog::logger> sim_log() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (spdlog::get("printsim")) return;
    auto l = spdlog::stderr_color_mt("printsim");
    l->set_pattern("printsim: %v");
    l->set_level(spdlog::level::warn);
  });
  return spdlog::get("printsim");
}

}  // namespace tp::sim
