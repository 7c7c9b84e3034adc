// host/app/printctl/cmd_bench_design.cpp: registers the bench design of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_bench_design(CLI::App& /*bench*/) {}

}  // namespace tp::host::cli
