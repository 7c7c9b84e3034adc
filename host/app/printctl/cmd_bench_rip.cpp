// host/app/printctl/cmd_bench_rip.cpp: registers the bench rip of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_bench_rip(CLI::App& /*bench*/) {}

}  // namespace tp::host::cli
