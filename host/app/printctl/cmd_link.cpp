// host/app/printctl/cmd_link.cpp: registers the link commands of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_link_commands(CLI::App& /*app*/) {}

}  // namespace tp::host::cli
