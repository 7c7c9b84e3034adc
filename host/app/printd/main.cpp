// host/app/printd/main.cpp: the printd daemon: hot folder, control socket, HTTP API, job queue, printing.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "host/daemon/daemon.h"
#include "rip/common/memory.h"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop.store(true); }

// The console's assets when --console-dir is not given: <bindir>/../share/printd/console (the
// installed layout, and the build tree's link to host/console), else the packaged place.
std::filesystem::path default_console_dir() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = exe.parent_path().parent_path() / "share/printd/console";
    if (fs::is_regular_file(beside / "index.html", ec)) return beside;
  }
  return "/usr/share/printd/console";
}
}  // namespace

int main(int argc, char** argv) {
  tp::rip::keep_memory_flat();  // peak memory must not grow with roll length
  CLI::App app{"printd: garment print daemon (hot folder, local socket, HTTP API, SQLite job queue)"};
  tp::host::DaemonConfig cfg;
  std::string state_dir = "/var/lib/printd", hot, out = "/var/lib/printd/out", socket;
  app.add_option("--state-dir", state_dir, "Job database, spool and socket")->capture_default_str();
  app.add_option("--hot-folder", hot, "Folder to watch for dropped jobs (folders with job.json, or .zip)");
  app.add_option("--out", out, "Job outputs go to <out>/<job-name>/")->capture_default_str();
  app.add_option("--socket", socket, "Control socket (default <state-dir>/printd.sock)");
  std::string printer;
  app.add_option("--printer", printer, "Override each job's printer: sim, usb or none")
      ->check(CLI::IsMember(tp::host::printer_choice_names()))
      ->each([&](const std::string& name) { cfg.printer_override = tp::host::parse_printer_choice(name); });
  app.add_option("--poll-ms", cfg.hot_folder_poll_ms, "Hot folder scan interval")->capture_default_str();
  app.add_option("--hot-settle-ms", cfg.hot_folder_settle_ms,
                 "A hot-folder entry is taken once its size held still this long and no file of it is open "
                 "for writing")->capture_default_str()->check(CLI::Range(0, 3600000));
  app.add_option("--client-timeout-ms", cfg.clients.request_timeout_ms,
                 "A control-socket client must send its whole request line within this")
      ->capture_default_str()->check(CLI::Range(50, 600000));
  app.add_option("--max-clients", cfg.clients.max_clients, "Control-socket clients served at once")
      ->capture_default_str()->check(CLI::Range(1, 1024));
  app.add_option("--max-crashes", cfg.max_crashes,
                 "A job on which printd crashed (fatal signal) this many times is failed, not retried")
      ->capture_default_str()->check(CLI::Range(1, 100));
  app.add_option("--max-unclean-exits", cfg.max_unclean_exits,
                 "A job printd vanished under (kill -9, out of memory, power loss) more than this many times is "
                 "failed, not resumed again")->capture_default_str()->check(CLI::Range(0, 1000));
  app.set_config("--config", "/etc/printd/printd.conf",
                 "Config file: one `option = value` line per long option (docs/daemon.md); absent is fine");
  app.allow_config_extras(CLI::config_extras_mode::error);  // a misspelt key must not pass unseen
  app.add_option("--listen", cfg.http.listen,
                 "HTTP API address host:port, or 'off'; beyond loopback needs --tls-cert/--tls-key and tokens")
      ->capture_default_str();
  app.add_option("--tls-cert", cfg.http.tls_cert, "PEM certificate for HTTPS");
  app.add_option("--tls-key", cfg.http.tls_key, "PEM private key for HTTPS");
  app.add_flag("--require-token", cfg.http.require_token,
               "Require bearer tokens on loopback too (always required beyond loopback)");
  std::size_t upload_mb = cfg.http.max_upload_bytes >> 20;
  app.add_option("--http-max-upload-mb", upload_mb, "Largest job upload accepted over HTTP, MiB")
      ->capture_default_str()->check(CLI::Range(1, 65536));
  app.add_option("--http-max-uploads", cfg.http.max_concurrent_uploads, "Uploads accepted at once; more get 503")
      ->capture_default_str()->check(CLI::Range(1, 256));
  app.add_option("--http-timeout-ms", cfg.http.read_timeout_ms,
                 "An HTTP client must keep sending (and reading) within this")
      ->capture_default_str()->check(CLI::Range(100, 600000));
  app.add_option("--http-threads", cfg.http.threads, "HTTP connections served at once (event streams included)")
      ->capture_default_str()->check(CLI::Range(2, 1024));
  app.add_option("--console-dir", cfg.http.console_dir,
                 "The operator console's assets, served at / (default <bindir>/../share/printd/console, "
                 "else /usr/share/printd/console)");
  app.add_option("--three-dir", cfg.http.three_dir, "three.js (libjs-three) served at /vendor/three/")
      ->capture_default_str();
  app.add_option("--event-log-size", cfg.event_log_size, "Events kept for Last-Event-ID replay")
      ->capture_default_str()->check(CLI::Range(16, 1000000));
  std::vector<std::string> limits;
  app.add_option("--limit", limits,
                 "NAME=VALUE: raise or lower a job limit (repeatable); defaults: " +
                     tp::host::describe_limits(cfg.limits));
  CLI11_PARSE(app, argc, argv);
  for (const auto& l : limits) {
    if (auto st = tp::host::set_limit(cfg.limits, l); !st) {
      std::fprintf(stderr, "printd: %s\n", st.error().message.c_str());
      return 2;
    }
  }

  if (cfg.http.console_dir.empty()) cfg.http.console_dir = default_console_dir();
  cfg.http.max_upload_bytes = upload_mb << 20;
  cfg.http.write_timeout_ms = cfg.http.read_timeout_ms;
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
