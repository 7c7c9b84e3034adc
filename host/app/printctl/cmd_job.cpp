// host/app/printctl/cmd_job.cpp: registers the job commands of printctl (not built yet).
#include "host/app/printctl/commands.h"

namespace tp::host::cli {

void register_job_commands(CLI::App& /*app*/) {}

}  // namespace tp::host::cli
