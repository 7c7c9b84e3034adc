// drivers/common/internal/log.h: the drivers layer's logger ("drivers").
#pragma once

#include <spdlog/spdlog.h>

#include <memory>

namespace tp::drivers {

/// The "drivers" logger, created on first use (stderr, shared with the process's sinks).
std::shared_ptr<spdlog::logger> drivers_log();

}  // namespace tp::drivers
