// host/app/printctl/commands.h: each printctl command group registers itself on the CLI here.
//
// One file per command group (cmd_<name>.cpp) keeps owners apart. A command's callback reports
// failure by throwing CLI::RuntimeError(exit_code) after printing its error to stderr.
#pragma once

#include <CLI/CLI.hpp>

namespace tp::host::cli {

// Job commands (cmd_job.cpp): run, validate.
void register_job_commands(CLI::App& app);
// Daemon client commands (cmd_daemon.cpp): submit, status, cancel.
void register_daemon_commands(CLI::App& app);
// HTTP API tokens (cmd_token.cpp): token add | list | revoke.
void register_token_commands(CLI::App& app);
// Printer link tools (cmd_link.cpp): wire-dump.
void register_link_commands(CLI::App& app);
// Garment tools (cmd_garment.cpp): garment (write a sample pattern and its 3D garment).
void register_garment_commands(CLI::App& app);
// Pattern tools (cmd_pattern.cpp): pattern suggest (stitches for a pattern that has none).
void register_pattern_commands(CLI::App& app);
// Colour tools (cmd_colour.cpp): calibrate, proof-check (design against printed fabric).
void register_colour_commands(CLI::App& app);
// The browser console (cmd_console.cpp): printsim and printd serving it, and its URL.
void register_console_commands(CLI::App& app);

// Benchmarks under `printctl bench` (cmd_bench_<what>.cpp).
void register_bench_link(CLI::App& bench);
void register_bench_garment(CLI::App& bench);
void register_bench_design(CLI::App& bench);
void register_bench_rip(CLI::App& bench);
void register_bench_nest(CLI::App& bench);

}  // namespace tp::host::cli
