// simulator/printsim/printer_memory.h: the simulated printer's non-volatile memory as a file
// (printsim --state): what the controller keeps across a power loss, so a printsim that is killed
// mid-job comes back as a printer that lost power (its job "lost", what it printed remembered).
#pragma once

#include <filesystem>

#include "device/firmware/controller.h"
#include "simulator/common/error.h"

namespace tp::sim {

/// Reads the memory file; a missing file is an empty memory. Fails with kInvalidArgument naming
/// the file and field if it is not one printsim wrote.
[[nodiscard]] Result<device::NonVolatileState> load_printer_memory(const std::filesystem::path& path);
/// Writes the memory file (to a temporary name, then renamed). Fails with kOutput naming the file.
[[nodiscard]] Status save_printer_memory(const std::filesystem::path& path, const device::NonVolatileState& state);

}  // namespace tp::sim
