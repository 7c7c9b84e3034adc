// host/daemon/daemon.cpp: printd's main loop (socket + hot folder) and its print worker.
#include "host/daemon/daemon.h"

#include <spdlog/spdlog.h>

#include <condition_variable>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "host/daemon/control_socket.h"
#include "host/daemon/hot_folder.h"
#include "host/daemon/intake.h"
#include "host/pipeline/run_job.h"
#include "host/store/job_store.h"

namespace tp::host {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string kHotOrigin = "hot-folder:";

json record_json(const JobRecord& r) {
  return {{"id", r.id},           {"name", r.name},       {"state", std::string(to_string(r.state))},
          {"stage", r.stage},     {"error", r.error},     {"out_dir", r.out_dir},
          {"origin", r.origin},   {"submitted_ms", r.submitted_ms}, {"updated_ms", r.updated_ms},
          {"last_acked_swath", r.last_acked_swath}, {"cancel_requested", r.cancel_requested}};
}

// The daemon's shared state between the main loop and the worker.
class Daemon {
 public:
  Daemon(const DaemonConfig& cfg, const std::atomic<bool>& stop) : cfg_(cfg), stop_(stop) {}

  Status run() {
    std::error_code ec;
    for (const auto& d : {cfg_.state_dir, spool_dir(), cfg_.out_dir}) {
      fs::create_directories(d, ec);
      if (ec) return fail(ErrorCode::kDaemon, d.string() + ": " + ec.message());
    }
    auto store = JobStore::open(cfg_.state_dir / "jobs.db");
    if (!store) return std::unexpected(store.error());
    if (auto n = store->requeue_interrupted(); n && *n > 0)
      spdlog::info("printd: {} interrupted job(s) queued again, resuming from their checkpoints", *n);
    fs::path sock_path = cfg_.socket_path.empty() ? default_socket_path(cfg_.state_dir) : cfg_.socket_path;
    auto sock = ControlSocket::listen(sock_path);
    if (!sock) return std::unexpected(sock.error());
    std::optional<HotFolder> hot;
    if (!cfg_.hot_folder.empty()) {
      hot.emplace(cfg_.hot_folder);
      if (!hot->prepare()) return fail(ErrorCode::kDaemon, cfg_.hot_folder.string() + ": cannot create hot folder");
    }
    spdlog::info("printd: listening on {}{}", sock_path.string(),
                 hot ? ", watching " + cfg_.hot_folder.string() : std::string());

    std::thread worker([this] { work(); });
    while (!stop_.load()) {
      sock->serve_one(cfg_.hot_folder_poll_ms, [&](const std::string& req) { return handle(*store, req); });
      if (hot) {
        for (const fs::path& entry : hot->scan()) take_from_hot_folder(*store, *hot, entry);
      }
    }
    {
      std::lock_guard lock(mu_);
      if (running_cancel_) running_cancel_->cancel();
    }
    wake_.notify_all();
    worker.join();
    spdlog::info("printd: stopped");
    return {};
  }

 private:
  fs::path spool_dir() const { return cfg_.state_dir / "spool"; }

  // Queues a checked package: copies or moves it into the spool, records it.
  Result<std::int64_t> enqueue(JobStore& store, const CheckedPackage& pkg, bool move, const std::string& origin) {
    fs::path spooled = unique_child(spool_dir(), pkg.job_name + pkg.path.extension().string());
    if (auto st = transfer_tree(pkg.path, spooled, move); !st) return std::unexpected(st.error());
    fs::path out = unique_child(cfg_.out_dir, pkg.job_name);
    auto id = store.enqueue(pkg.job_name, spooled.string(), out.string(), origin);
    if (id) {
      spdlog::info("printd: job {} '{}' queued from {}", *id, pkg.job_name, origin);
      wake_.notify_all();
    }
    return id;
  }

  void take_from_hot_folder(JobStore& store, const HotFolder& hot, const fs::path& entry) {
    auto checked = check_package(entry, spool_dir());
    if (!checked) {
      spdlog::warn("printd: {} refused: {}", entry.filename().string(), checked.error().message);
      fs::path dest = unique_child(hot.failed_dir(), entry.filename().string());
      if (transfer_tree(entry, dest / entry.filename(), true))
        std::ofstream(dest / "error.txt") << checked.error().message << "\n";
      return;
    }
    if (auto id = enqueue(store, *checked, true, kHotOrigin + entry.filename().string()); !id)
      spdlog::error("printd: {}: {}", entry.string(), id.error().message);
  }

  std::string handle(JobStore& store, const std::string& request) {
    json req = json::parse(request, nullptr, false);
    if (req.is_discarded() || !req.is_object() || !req.contains("op") || !req["op"].is_string())
      return json{{"ok", false}, {"error", "request must be a JSON object with \"op\""}}.dump();
    const std::string op = req["op"];
    auto err = [](const std::string& m) { return json{{"ok", false}, {"error", m}}.dump(); };
    if (op == "ping") return json{{"ok", true}}.dump();
    if (op == "submit") {
      if (!req.contains("package") || !req["package"].is_string()) return err("submit needs \"package\": a path");
      fs::path p = req["package"].get<std::string>();
      if (!p.is_absolute()) return err("submit: package path must be absolute");
      auto checked = check_package(p, spool_dir());
      if (!checked) return err(checked.error().message);
      auto id = enqueue(store, *checked, false, "socket");
      if (!id) return err(id.error().message);
      return json{{"ok", true}, {"id", *id}, {"name", checked->job_name}}.dump();
    }
    if (op == "status") {
      if (req.contains("id")) {
        if (!req["id"].is_number_integer()) return err("status: \"id\" must be an integer");
        auto rec = store.get(req["id"].get<std::int64_t>());
        if (!rec) return err(rec.error().message);
        if (!*rec) return err("no job " + std::to_string(req["id"].get<std::int64_t>()));
        json j = record_json(**rec);
        if (auto st = store.stages((*rec)->id)) {
          j["stages"] = json::array();
          for (const auto& s : *st) j["stages"].push_back({{"stage", s.stage}, {"state", s.state}, {"seconds", s.seconds}});
        }
        return json{{"ok", true}, {"job", j}}.dump();
      }
      auto list = store.list(req.value("limit", 50));
      if (!list) return err(list.error().message);
      json jobs = json::array();
      for (const auto& r : *list) jobs.push_back(record_json(r));
      return json{{"ok", true}, {"jobs", jobs}}.dump();
    }
    if (op == "cancel") {
      if (!req.contains("id") || !req["id"].is_number_integer()) return err("cancel needs \"id\": an integer");
      std::int64_t id = req["id"];
      auto st = store.request_cancel(id);
      if (!st) return err(st.error().message);
      if (*st == JobState::kRunning) {
        std::lock_guard lock(mu_);
        if (running_id_ == id && running_cancel_) running_cancel_->cancel();
      }
      return json{{"ok", true}, {"id", id}, {"state", *st == JobState::kRunning ? "cancelling" : "cancelled"}}.dump();
    }
    return err("unknown op \"" + op + "\" (ping, submit, status, cancel)");
  }

  // The worker: one job at a time, since there is one printer.
  void work() {
    auto store = JobStore::open(cfg_.state_dir / "jobs.db");
    if (!store) {
      spdlog::error("printd: worker: {}", store.error().message);
      return;
    }
    while (!stop_.load()) {
      auto next = store->claim_next();
      if (!next || !*next) {
        std::unique_lock lock(mu_);
        wake_.wait_for(lock, std::chrono::milliseconds(500));
        continue;
      }
      run_one(*store, **next);
    }
  }

  void run_one(JobStore& store, const JobRecord& rec) {
    geometry::CancelToken cancel;
    {
      std::lock_guard lock(mu_);
      running_id_ = rec.id;
      running_cancel_ = cancel;
    }
    spdlog::info("printd: job {} '{}' running{}", rec.id, rec.name,
                 rec.last_acked_swath >= 0 ? " (resuming after swath " + std::to_string(rec.last_acked_swath) + ")" : "");
    Status result = {};
    auto job = open_spooled_job(rec.package);
    if (!job) {
      result = std::unexpected(job.error());
    } else {
      RunOptions opt;
      opt.out_dir = rec.out_dir;
      opt.printer_override = cfg_.printer_override;
      opt.resume_after_swath = rec.last_acked_swath;
      // The job's plan lives in its state: a resume or a restart prints the garment and marker
      // made the first time (docs/plan-storage.md).
      opt.plan_dir = cfg_.state_dir / "plans" / std::to_string(rec.id);
      (void)store.set_plan_dir(rec.id, opt.plan_dir.string());
      opt.job_id = rec.id;
      opt.on_stage = [&](Stage s, StageState st, double secs) {
        (void)store.set_stage(rec.id, std::string(to_string(s)), std::string(to_string(st)), secs);
        // The cancel request may come from another printctl process, through the database.
        if (auto r = store.get(rec.id); r && *r && (*r)->cancel_requested) cancel.cancel();
      };
      opt.on_checkpoint = [&](std::int64_t swath) {
        (void)store.set_checkpoint(rec.id, swath);
        if (auto r = store.get(rec.id); r && *r && (*r)->cancel_requested) cancel.cancel();
      };
      result = run_job(*job, opt, cancel);
    }
    {
      std::lock_guard lock(mu_);
      running_id_ = 0;
      running_cancel_.reset();
    }
    // Stopping the daemon interrupts the job; it stays "running" and resumes at the next start.
    if (stop_.load() && !result && result.error().code == ErrorCode::kCancelled) {
      spdlog::info("printd: job {} interrupted by shutdown", rec.id);
      return;
    }
    JobState final_state = result ? JobState::kDone
                                  : result.error().code == ErrorCode::kCancelled ? JobState::kCancelled
                                                                                 : JobState::kFailed;
    std::string error = result ? std::string() : result.error().message;
    (void)store.set_state(rec.id, final_state, error);
    if (result) spdlog::info("printd: job {} '{}' done", rec.id, rec.name);
    else spdlog::warn("printd: job {} '{}' {}: {}", rec.id, rec.name, to_string(final_state), error);
    file_hot_folder_entry(rec, final_state, error);
  }

  // A job that came from the hot folder goes back there, under done/ or failed/, with its report.
  void file_hot_folder_entry(const JobRecord& rec, JobState state, const std::string& error) {
    if (cfg_.hot_folder.empty() || rec.origin.rfind(kHotOrigin, 0) != 0) return;
    const std::string entry = rec.origin.substr(kHotOrigin.size());
    fs::path dest = unique_child(cfg_.hot_folder / (state == JobState::kDone ? "done" : "failed"), entry);
    if (!transfer_tree(rec.package, dest / entry, true)) return;
    std::error_code ec;
    fs::path unpacked = fs::path(rec.package + ".unpacked");
    fs::remove_all(unpacked, ec);
    fs::copy_file(fs::path(rec.out_dir) / "report.json", dest / "report.json", ec);
    if (!error.empty()) std::ofstream(dest / "error.txt") << error << "\n";
  }

  const DaemonConfig& cfg_;
  const std::atomic<bool>& stop_;
  std::mutex mu_;
  std::condition_variable wake_;
  std::int64_t running_id_ = 0;
  std::optional<geometry::CancelToken> running_cancel_;
};

}  // namespace

Status run_daemon(const DaemonConfig& config, const std::atomic<bool>& stop) {
  Daemon d(config, stop);
  return d.run();
}

}  // namespace tp::host
