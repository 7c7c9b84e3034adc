// rip/common/internal/log.h: the rip layer's spdlog logger (private: spdlog stays out of public headers).
#pragma once

#include <memory>

#include <spdlog/spdlog.h>

namespace tp::rip {

/// The one logger of rip/ ("rip"), created on first use.
spdlog::logger& logger();

}  // namespace tp::rip
