// host/app/printctl/cmd_bench_link.cpp: registers the bench link of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_bench_link(CLI::App& /*bench*/) {}

}  // namespace tp::host::cli
