// simulator/printsim/printer_sim.h: printsim itself: a umockdev testbed holding the emulated USB
// printer and GPIO chip of the cutting table, the printer's firmware behind them, fault
// injection from a scenario, and a command run under the umockdev preload so that its real
// libusb and libgpiod code talks to them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "simulator/common/error.h"

namespace tp::sim {

struct SimOptions {
  std::filesystem::path out_dir = ".";
  bool job_dirs = false;
  std::optional<std::filesystem::path> scenario;
  std::optional<std::filesystem::path> printer_model;  ///< model file; built-in tp-sim-1600 otherwise
  double speed = 0;           ///< modelled seconds per wall second, 0 = as fast as data comes
  bool fabric = true;         ///< lay drops and write fabric images
  /// The printer's non-volatile memory (printsim --state): read at start, written as the job
  /// goes; with it a printsim killed mid-job comes back as a printer that lost power.
  std::optional<std::filesystem::path> state_file;
  unsigned reap_hold_ms = 2;  ///< see UsbPrinterDevice
  std::vector<std::string> command;
};

/// Environment variable set for the command: its value is the output folder.
inline constexpr const char* kPrintsimEnv = "TP_PRINTSIM";

/// Runs `options.command` against the simulated printer and cutter and returns its exit status
/// (128 + signal if it was killed). Fails with kTestbed, kScenario or kChild before the command
/// runs, or kOutput if the job outputs could not be written.
[[nodiscard]] Result<int> run_printsim(const SimOptions& options);

}  // namespace tp::sim
