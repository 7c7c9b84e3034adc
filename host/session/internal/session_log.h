// host/session/internal/session_log.h: the print session's logger ("session").
#pragma once

#include <spdlog/spdlog.h>

#include <memory>

namespace tp::host {

/// The "session" logger, sharing the default logger's sinks; created on first use.
std::shared_ptr<spdlog::logger> session_log();

}  // namespace tp::host
