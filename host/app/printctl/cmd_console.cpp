// host/app/printctl/cmd_console.cpp: `printctl console`: printsim with printd inside it serving the
// operator console and design studio on loopback, and the URL for a person to open.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "host/app/printctl/commands.h"

namespace tp::host::cli {

namespace {

namespace fs = std::filesystem;

struct ConsoleOptions {
  std::string out = "out/console";
  int port = 8631;
  std::string example;
  std::string printer_model;
  std::string console_dir;
  bool fresh = false;
};

volatile sig_atomic_t g_child = 0;
void forward_signal(int) {
  if (g_child > 0) ::kill(-g_child, SIGTERM);
}

[[noreturn]] void fail_with(const std::string& message, int code) {
  std::fprintf(stderr, "printctl console: %s\n", message.c_str());
  throw CLI::RuntimeError(code);
}

fs::path self_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) fail_with("cannot find this executable (/proc/self/exe): " + ec.message(), 2);
  return exe.parent_path();
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `argv` with its output appended to `log` in a process group of its own; returns the pid.
pid_t spawn(const std::vector<std::string>& argv, const fs::path& log) {
  const pid_t pid = ::fork();
  if (pid < 0) fail_with("fork failed", 2);
  if (pid == 0) {
    ::setpgid(0, 0);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    std::fprintf(stderr, "printctl console: cannot run %s\n", args[0]);
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  return pid;
}

int run_console(const ConsoleOptions& o) {
  const fs::path bin = self_dir();
  const fs::path printd = bin / "printd", printsim = bin / "printsim", printctl = bin / "printctl";
  for (const fs::path& p : {printd, printsim})
    if (::access(p.c_str(), X_OK) != 0)
      fail_with(p.string() + " is missing (printd and printsim go beside printctl)", 2);
  if (o.port < 0 || o.port > 65535) fail_with("--port " + std::to_string(o.port) + ": not a TCP port", 2);
  const fs::path out = fs::absolute(o.out);
  std::error_code ec;
  if (o.fresh) fs::remove_all(out, ec);
  fs::create_directories(out, ec);
  if (ec) fail_with(out.string() + ": " + ec.message(), 2);

  // The printer printsim plays: a model file, or the one an example job plans for.
  fs::path model;
  if (!o.printer_model.empty()) {
    model = fs::absolute(o.printer_model);
    if (!fs::is_regular_file(model, ec)) fail_with("--printer-model " + model.string() + ": no such file", 2);
  } else if (!o.example.empty()) {
    model = out / "printer-model.txt";
    const std::string cmd =
        "'" + printctl.string() + "' printer-model '" + o.example + "' --out '" + model.string() + "'";
    if (o.example.find('\'') != std::string::npos || std::system(cmd.c_str()) != 0)
      fail_with("--example " + o.example + ": no printer model from that job", 1);
  }
  const fs::path conf = out / "none.conf";
  if (!fs::exists(conf, ec)) std::ofstream(conf) << "# printctl console gives every setting on the command line\n";

  const fs::path log = out / "printd.log";
  fs::remove(log, ec);
  std::vector<std::string> argv = {printsim.string(), "run", "--job-dirs", "--out", out.string()};
  if (!model.empty()) argv.insert(argv.end(), {"--printer", model.string()});
  argv.insert(argv.end(), {"--", printd.string(), "--state-dir", (out / ".printd").string(), "--out", out.string(),
                           "--config", conf.string(), "--listen", "127.0.0.1:" + std::to_string(o.port)});
  if (!o.console_dir.empty()) argv.insert(argv.end(), {"--console-dir", fs::absolute(o.console_dir).string()});

  struct sigaction sa {};
  sa.sa_handler = forward_signal;
  ::sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  const pid_t child = spawn(argv, log);
  g_child = child;

  // Up when printd logs its HTTP address (the real port, also when --port 0 picked one).
  std::string url;
  int status = 0;
  for (int i = 0; i < 300 && url.empty(); ++i) {
    const std::string text = read_text(log);
    const size_t at = text.find("HTTP API on http://");
    if (at != std::string::npos) {
      const size_t end = text.find_first_of(" \r\n", at + 12);
      url = text.substr(at + 12, end - at - 12) + "/";
      break;
    }
    if (::waitpid(child, &status, WNOHANG) == child) {
      std::fputs(text.c_str(), stderr);
      fail_with("printd did not start (log: " + log.string() + ")", 1);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (url.empty()) {
    ::kill(-child, SIGTERM);
    ::waitpid(child, &status, 0);
    fail_with("printd gave no HTTP address within 30 s (log: " + log.string() + ")", 1);
  }
  std::printf(
      "\n  The print room console is running:  %s\n  The design studio:                  %sstudio/\n\n"
      "  Open it in Chromium or Firefox. Drop a job .zip on the page to print it, for example:\n"
      "    python3 -m zipfile -c /tmp/top-strokes.zip examples/top-strokes/*\n"
      "  Outputs and the simulated fabric land in %s/. Ctrl-C stops printd and printsim.\n\n",
      url.c_str(), url.c_str(), out.c_str());
  std::fflush(stdout);
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  g_child = 0;
  // Stopped by Ctrl-C or a TERM we forwarded: a normal end.
  if (WIFEXITED(status)) return WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 143 ? 0 : WEXITSTATUS(status);
  return WTERMSIG(status) == SIGTERM || WTERMSIG(status) == SIGINT ? 0 : 1;
}

}  // namespace

void register_console_commands(CLI::App& app) {
  static ConsoleOptions o;
  CLI::App* c = app.add_subcommand(
      "console", "Start printsim with printd inside it serving the console and studio; print the URL");
  c->add_option("--out", o.out, "Outputs, fabric and printd's state (kept between runs)")->capture_default_str();
  c->add_option("--port", o.port, "Loopback port of the HTTP API and console (0: any free one)")->capture_default_str();
  c->add_option("--example", o.example, "A job folder or .zip whose printer model printsim plays");
  c->add_option("--printer-model", o.printer_model, "A printer model file for printsim (printctl printer-model)");
  c->add_option("--console-dir", o.console_dir, "The console's page assets (default: printd's installed ones)");
  c->add_flag("--fresh", o.fresh, "Start with an empty --out folder (no history)");
  c->callback([] {
    const int code = run_console(o);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace tp::host::cli
