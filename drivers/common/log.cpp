// drivers/common/log.cpp: the drivers layer's logger.
#include "drivers/common/internal/log.h"

#include <mutex>

namespace tp::drivers {

std::shared_ptr<spdlog::logger> drivers_log() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (spdlog::get("drivers")) return;
    // Share the default logger's sinks so the application decides where log lines go.
    auto def = spdlog::default_logger();
    auto l = std::make_shared<spdlog::logger>("drivers", def->sinks().begin(), def->sinks().end());
    l->set_level(def->level());
    spdlog::register_logger(l);
  });
  return spdlog::get("drivers");
}

}  // namespace tp::drivers
