// host/app/printctl/cmd_daemon.cpp: printctl submit [--wait, with progress] | status | cancel, talking to printd.
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <unistd.h>

#include "host/app/printctl/commands.h"
#include "host/app/printctl/progress_view.h"
#include "host/common/text.h"
#include "host/daemon/control_socket.h"

namespace tp::host::cli {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

struct DaemonArgs {
  std::string state_dir = "/var/lib/printd";
  std::string socket;
  fs::path socket_path() const { return socket.empty() ? default_socket_path(state_dir) : fs::path(socket); }
};

void add_daemon_options(CLI::App* cmd, DaemonArgs& a) {
  cmd->add_option("--state-dir", a.state_dir, "printd's state directory")->capture_default_str();
  cmd->add_option("--socket", a.socket, "printd's control socket (default <state-dir>/printd.sock)");
}

// Sends a request and returns the reply object, or fails the command with the daemon's error.
json request(const DaemonArgs& a, const json& req) {
  auto reply = socket_request(a.socket_path(), dump_json(req));
  if (!reply) {
    std::fprintf(stderr, "printctl: %s\n", reply.error().message.c_str());
    throw CLI::RuntimeError(3);
  }
  json r = json::parse(*reply, nullptr, false);
  if (r.is_discarded() || !r.is_object()) {
    std::fprintf(stderr, "printctl: unreadable reply from printd\n");
    throw CLI::RuntimeError(3);
  }
  if (!r.value("ok", false)) {
    std::fprintf(stderr, "printctl: %s\n", r.value("error", std::string("request failed")).c_str());
    throw CLI::RuntimeError(1);
  }
  return r;
}

void print_job_line(const json& j) {
  std::printf("%-5lld %-10s %-9s %-32s %s\n", static_cast<long long>(j.value("id", 0LL)),
              j.value("state", std::string()).c_str(), j.value("stage", std::string()).c_str(),
              j.value("name", std::string()).c_str(), j.value("error", std::string()).substr(0, 60).c_str());
}

}  // namespace

void register_daemon_commands(CLI::App& app) {
  static DaemonArgs args;
  static std::string package;
  static bool wait = false;
  static bool reprint = false;
  static double wait_timeout_s = 3600;
  CLI::App* submit = app.add_subcommand("submit", "Queue a job (folder or .zip) on the running printd");
  submit->add_option("job", package, "Job package")->required();
  submit->add_flag("--wait", wait, "Wait until the job ends; exit 0 only if it is done");
  submit->add_option("--timeout", wait_timeout_s, "Seconds to wait with --wait");
  submit->add_flag("--reprint", reprint,
                   "Queue it even if the same package is already queued, running or done (a retry without "
                   "this never prints twice)");
  add_daemon_options(submit, args);
  submit->callback([] {
    json req = {{"op", "submit"}, {"package", fs::absolute(package).lexically_normal().string()}};
    if (reprint) req["reprint"] = true;
    json r = request(args, req);
    const long long id = r.value("id", 0LL);
    if (r.value("duplicate", false))
      std::printf("job %lld '%s' already %s with the same content (not queued again; --reprint to print it again)\n",
                  id, r.value("name", std::string()).c_str(), r.value("state", std::string("queued")).c_str());
    else
      std::printf("queued job %lld '%s'\n", id, r.value("name", std::string()).c_str());
    if (!wait) return;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_timeout_s);
    // Progress comes from the daemon's event log (the events the HTTP API streams), from the
    // start of the log so a job that already began shows its earlier stages too.
    ProgressView view(stderr, ::isatty(2) != 0);
    std::uint64_t after = 0;
    bool events = true;
    const auto pump = [&](int wait_ms) {
      if (!events) return;
      auto reply = socket_request(
          args.socket_path(), dump_json(json{{"op", "events"}, {"after", after}, {"job", id}, {"wait_ms", wait_ms}}));
      json e = reply ? json::parse(*reply, nullptr, false) : json();
      if (!e.is_object() || !e.value("ok", false)) {
        events = false;  // an older printd: status polling only
        return;
      }
      after = e.value("last", after);
      for (const json& ev : e["events"]) {
        if (ev.value("type", "") != "progress" || ev.value("job_id", 0LL) != id) continue;
        const std::string stage = ev.value("stage", ""), st = ev.value("state", "");
        if (ev.contains("detail")) view.progress(stage, ev.value("fraction", 0.0), ev.value("detail", ""));
        else view.stage(stage, st, ev.value("seconds", 0.0));
      }
    };
    for (;;) {
      pump(500);
      json s = request(args, {{"op", "status"}, {"id", id}})["job"];
      const std::string state = s.value("state", "");
      if (state == "done" || state == "failed" || state == "cancelled") pump(0);  // the last stages' events
      if (state == "done") {
        std::printf("job %lld done: %s\n", id, s.value("out_dir", std::string()).c_str());
        return;
      }
      if (state == "failed" || state == "cancelled") {
        std::fprintf(stderr, "job %lld %s: %s\n", id, state.c_str(), s.value("error", std::string()).c_str());
        throw CLI::RuntimeError(1);
      }
      if (std::chrono::steady_clock::now() > deadline) {
        std::fprintf(stderr, "job %lld still %s after %.0f s\n", id, state.c_str(), wait_timeout_s);
        throw CLI::RuntimeError(4);
      }
      if (!events) std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
  });

  static long long status_id = -1;
  static bool status_json = false;
  CLI::App* status = app.add_subcommand("status", "Show printd's jobs, or one job with its stages");
  status->add_option("id", status_id, "Job id");
  status->add_flag("--json", status_json, "Print the daemon's JSON reply");
  add_daemon_options(status, args);
  status->callback([] {
    json req = {{"op", "status"}};
    if (status_id >= 0) req["id"] = status_id;
    json r = request(args, req);
    if (status_json) {
      std::printf("%s\n", dump_json(r, 2).c_str());
      return;
    }
    std::printf("%-5s %-10s %-9s %-32s %s\n", "ID", "STATE", "STAGE", "NAME", "ERROR");
    if (r.contains("job")) {
      print_job_line(r["job"]);
      for (const auto& s : r["job"].value("stages", json::array()))
        std::printf("      %-10s %-9s %.2f s\n", s.value("stage", std::string()).c_str(),
                    s.value("state", std::string()).c_str(), s.value("seconds", 0.0));
    } else {
      for (const auto& j : r["jobs"]) print_job_line(j);
    }
  });

  static long long cancel_id = -1;
  CLI::App* cancel = app.add_subcommand("cancel", "Cancel a queued or running job");
  cancel->add_option("id", cancel_id, "Job id")->required();
  add_daemon_options(cancel, args);
  cancel->callback([] {
    json r = request(args, {{"op", "cancel"}, {"id", cancel_id}});
    std::printf("job %lld %s\n", cancel_id, r.value("state", std::string()).c_str());
  });
}

}  // namespace tp::host::cli
