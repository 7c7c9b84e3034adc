// host/app/printctl/cmd_daemon.cpp: registers the daemon commands of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_daemon_commands(CLI::App& /*app*/) {}

}  // namespace tp::host::cli
