// host/session/session_log.cpp: the print session's logger.
#include "host/session/internal/session_log.h"

#include <mutex>

namespace tp::host {

std::shared_ptr<spdlog::logger> session_log() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (spdlog::get("session")) return;
    auto def = spdlog::default_logger();
    auto l = std::make_shared<spdlog::logger>("session", def->sinks().begin(), def->sinks().end());
    l->set_level(def->level());
    spdlog::register_logger(l);
  });
  return spdlog::get("session");
}

}  // namespace tp::host
