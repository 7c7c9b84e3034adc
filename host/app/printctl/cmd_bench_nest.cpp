// host/app/printctl/cmd_bench_nest.cpp: registers the bench nest of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_bench_nest(CLI::App& /*bench*/) {}

}  // namespace tp::host::cli
