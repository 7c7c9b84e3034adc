// host/app/printd/main.cpp: the printd daemon: hot folder, control socket, job queue, printing.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <atomic>
#include <csignal>
#include <cstdio>

#include "host/daemon/daemon.h"
#include "rip/common/memory.h"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop.store(true); }
}  // namespace

int main(int argc, char** argv) {
  tp::rip::keep_memory_flat();  // peak memory must not grow with roll length
  CLI::App app{"printd: garment print daemon (hot folder, local socket, SQLite job queue)"};
  tp::host::DaemonConfig cfg;
  std::string state_dir = "/var/lib/printd", hot, out = "/var/lib/printd/out", socket;
  app.add_option("--state-dir", state_dir, "Job database, spool and socket")->capture_default_str();
  app.add_option("--hot-folder", hot, "Folder to watch for dropped jobs (folders with job.json, or .zip)");
  app.add_option("--out", out, "Job outputs go to <out>/<job-name>/")->capture_default_str();
  app.add_option("--socket", socket, "Control socket (default <state-dir>/printd.sock)");
  app.add_option("--printer", cfg.printer_override, "Override each job's printer: sim, usb or none")
      ->check(CLI::IsMember({"sim", "usb", "none"}));
  app.add_option("--poll-ms", cfg.hot_folder_poll_ms, "Hot folder scan interval")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  cfg.state_dir = state_dir;
  cfg.hot_folder = hot;
  cfg.out_dir = out;
  cfg.socket_path = socket;
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGPIPE, SIG_IGN);
  spdlog::set_pattern("%Y-%m-%d %H:%M:%S.%e %^%l%$ %v");

  auto st = tp::host::run_daemon(cfg, g_stop);
  if (!st) {
    std::fprintf(stderr, "printd: %s\n", st.error().message.c_str());
    return 1;
  }
  return 0;
}
