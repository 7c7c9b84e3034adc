// host/app/printctl/main.cpp: the printctl command line: jobs, daemon client, tools, benchmarks.
#include <cstdio>

#include "host/app/printctl/commands.h"
#include "rip/common/memory.h"

int main(int argc, char** argv) {
  tp::rip::keep_memory_flat();  // peak memory must not grow with roll length
  CLI::App app{"printctl: garment print controller command line"};
  app.require_subcommand(1);
  app.fallthrough();

  tp::host::cli::register_job_commands(app);
  tp::host::cli::register_daemon_commands(app);
  tp::host::cli::register_token_commands(app);
  tp::host::cli::register_link_commands(app);
  tp::host::cli::register_garment_commands(app);
  tp::host::cli::register_pattern_commands(app);
  tp::host::cli::register_colour_commands(app);
  tp::host::cli::register_console_commands(app);

  CLI::App* bench = app.add_subcommand("bench", "Measure a stage and print key=value figures");
  bench->require_subcommand(1);
  tp::host::cli::register_bench_link(*bench);
  tp::host::cli::register_bench_garment(*bench);
  tp::host::cli::register_bench_design(*bench);
  tp::host::cli::register_bench_rip(*bench);
  tp::host::cli::register_bench_nest(*bench);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return 0;
}
