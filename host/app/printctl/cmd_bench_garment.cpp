// host/app/printctl/cmd_bench_garment.cpp: registers the bench garment of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_bench_garment(CLI::App& /*bench*/) {}

}  // namespace tp::host::cli
