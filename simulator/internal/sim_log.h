// simulator/internal/sim_log.h: the simulator's logger ("printsim").
#pragma once

#include <spdlog/spdlog.h>

#include <memory>

namespace tp::sim {

/// The "printsim" logger (stderr), created on first use.
std::shared_ptr<spdlog::logger> sim_log();

}  // namespace tp::sim
