// host/app/printctl/cmd_garment.cpp: registers the garment commands of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_garment_commands(CLI::App& /*app*/) {}

}  // namespace tp::host::cli
