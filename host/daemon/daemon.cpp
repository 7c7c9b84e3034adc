// host/daemon/daemon.cpp: printd's main loop (socket + hot folder) and its print worker.
#include "host/daemon/daemon.h"

#include <spdlog/spdlog.h>

#include <condition_variable>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "host/common/atomic_file.h"
#include "host/common/failure_report.h"
#include "host/common/text.h"
#include "host/daemon/crash_guard.h"
#include "host/daemon/events/event_log.h"
#include "host/daemon/hot_folder.h"
#include "host/daemon/intake.h"
#include "host/daemon/printer_view.h"
#include "host/daemon/requests/request_handler.h"
#include "host/pipeline/job_stitch_check.h"
#include "host/pipeline/printer_model.h"
#include "host/pipeline/run_job.h"
#include "host/store/job_store.h"

namespace tp::host {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string kHotOrigin = "hot-folder:";

// The state directory and what is in it are the daemon's alone (jobs may be confidential).
Status make_state_dirs(const std::vector<fs::path>& dirs) {
  std::error_code ec;
  for (const auto& d : dirs) {
    fs::create_directories(d, ec);
    if (ec) return fail(ErrorCode::kDaemon, d.string() + ": " + ec.message());
    fs::permissions(d, fs::perms::owner_all, ec);
    if (ec) return fail(ErrorCode::kDaemon, d.string() + ": cannot make it private (0700): " + ec.message());
  }
  return {};
}

void write_error_txt(const fs::path& path, const std::string& error) {
  if (auto st = write_file_atomic(path, error + "\n"); !st) spdlog::warn("printd: {}", st.error().message);
}

// The daemon's shared state between the main loop, the socket's client threads and the worker.
class Daemon {
 public:
  Daemon(const DaemonConfig& cfg, const std::atomic<bool>& stop)
      : cfg_(cfg), stop_(stop), events_(cfg.event_log_size) {}

  Status run() {
    if (auto st = make_state_dirs({cfg_.state_dir, spool_dir(), packages_dir()}); !st) return st;
    std::error_code ec;
    fs::create_directories(cfg_.out_dir, ec);
    if (ec) return fail(ErrorCode::kDaemon, cfg_.out_dir.string() + ": " + ec.message());
    auto store = JobStore::open(db_path());
    if (!store) return std::unexpected(store.error());
    for (const char* suffix : {"", "-wal", "-shm"}) {
      fs::path f = db_path();
      f += suffix;
      if (fs::exists(f, ec)) fs::permissions(f, fs::perms::owner_read | fs::perms::owner_write, ec);
    }
    recover(*store);
    install_crash_guard(crash_marker_path());

    // Each socket client runs on its own thread with its own store connection (declared before
    // the socket, whose destructor waits for those threads).
    const auto handler = [this](const std::string& req) {
      auto client_store = JobStore::open(db_path());
      if (!client_store) return dump_json(json{{"ok", false}, {"error", client_store.error().message}});
      return handle_request(*client_store, req, hooks(*client_store));
    };
    // The HTTP API asks the same handler, on its own threads with their own store connections.
    std::unique_ptr<HttpServer> http;
    if (cfg_.http.listen != "off") {
      HttpBackend backend;
      backend.request = [this](JobStore& s, const std::string& req) { return handle_request(s, req, hooks(s)); };
      backend.db_path = db_path();
      backend.upload_dir = cfg_.state_dir / "uploads";
      backend.events = &events_;
      backend.printer_status = [this] { return printer_status(); };
      if (auto st = make_state_dirs({backend.upload_dir}); !st) return st;
      auto server = HttpServer::start(cfg_.http, std::move(backend));
      if (!server) return std::unexpected(server.error());
      http = std::move(*server);
    }
    fs::path sock_path = cfg_.socket_path.empty() ? default_socket_path(cfg_.state_dir) : cfg_.socket_path;
    auto sock = ControlSocket::listen(sock_path);
    if (!sock) return std::unexpected(sock.error());
    std::optional<HotFolder> hot;
    if (!cfg_.hot_folder.empty()) {
      hot.emplace(cfg_.hot_folder, std::chrono::milliseconds(cfg_.hot_folder_settle_ms));
      if (!hot->prepare()) return fail(ErrorCode::kDaemon, cfg_.hot_folder.string() + ": cannot create hot folder");
    }
    spdlog::info("printd: listening on {}{}", sock_path.string(),
                 hot ? ", watching " + cfg_.hot_folder.string() : std::string());

    std::thread worker([this] { work(); });
    while (!stop_.load()) {
      sock->serve(cfg_.hot_folder_poll_ms, handler, cfg_.clients);
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
    http.reset();
    spdlog::info("printd: stopped");
    return {};
  }

 private:
  fs::path spool_dir() const { return cfg_.state_dir / "spool"; }
  fs::path db_path() const { return cfg_.state_dir / "jobs.db"; }
  fs::path crash_marker_path() const { return cfg_.state_dir / "crash.marker"; }
  // Every accepted package is kept here by content hash, so a job can be reprinted after its
  // spooled copy is gone.
  fs::path packages_dir() const { return cfg_.state_dir / "packages"; }

  void publish_job(std::int64_t id, JobState state, const std::string& error = {}) {
    json data = {{"state", std::string(to_string(state))}};
    if (!error.empty()) data["error"] = printable_utf8(error);
    events_.publish("job", id, std::move(data));
  }

  json printer_status() {
    std::lock_guard lock(mu_);
    return json{{"printer", cfg_.printer_override ? std::string(to_string(*cfg_.printer_override)) : std::string("each job's own")},
                {"state", running_id_ != 0 ? "printing" : "idle"},
                {"job_id", running_id_},
                {"stage", running_stage_},
                {"last_acked_swath", running_swath_},
                {"model", printer_model_},
                {"ieee1284_id", printer_ieee1284_},
                {"counters", {{"jobs_run", jobs_run_}, {"swaths_acked", swaths_acked_}}},
                {"last_event", events_.last_seq()},
                {"device", printer_view_.snapshot()}};
  }

  // A job that was running when printd died: failed if printd crashed on it, else resumed.
  void recover(JobStore& store) {
    if (auto m = take_crash_marker(crash_marker_path())) {
      auto rec = store.get(m->job_id);
      const std::string stage = rec && *rec ? (*rec)->stage : std::string("?");
      const std::string reason = "printd crashed (" + signal_name(m->signal) + ") while running this job, in stage " +
                                 stage + "; not retried (printd --max-crashes=" + std::to_string(cfg_.max_crashes) + ")";
      auto st = store.record_crash(m->job_id, reason, cfg_.max_crashes);
      if (st && *st == JobState::kFailed) {
        spdlog::error("printd: job {}: {}", m->job_id, reason);
        if (rec && *rec) finish_files(**rec, JobState::kFailed, reason);
      } else if (st) {
        spdlog::warn("printd: job {} crashed printd ({}); queued again", m->job_id, signal_name(m->signal));
      }
    }
    auto n = store.requeue_interrupted(cfg_.max_unclean_exits);
    if (n && n->requeued > 0)
      spdlog::info("printd: {} interrupted job(s) queued again, resuming from their checkpoints", n->requeued);
    if (n && n->failed > 0)
      spdlog::error("printd: {} job(s) failed: printd stopped more than {} times while running them", n->failed,
                    cfg_.max_unclean_exits);
  }

  RequestHooks hooks(JobStore& store) {
    RequestHooks h;
    h.submit = [this, &store](const fs::path& package, bool reprint) -> Result<json> {
      return submit(store, package, reprint);
    };
    h.reprint = [this, &store](std::int64_t id) -> Result<json> {
      auto rec = store.get(id);
      if (!rec) return std::unexpected(rec.error());
      if (!*rec) return fail(ErrorCode::kJob, "no job " + std::to_string(id));
      for (const char* ext : {".zip", ""}) {
        const fs::path kept = packages_dir() / ((*rec)->content_hash + ext);
        std::error_code ec;
        if (!(*rec)->content_hash.empty() && fs::exists(kept, ec)) return submit(store, kept, true);
      }
      return fail(ErrorCode::kJob, "job " + std::to_string(id) + ": its package is no longer kept; submit it again");
    };
    h.events = [this](std::uint64_t after, std::int64_t job, int wait_ms) {
      EventBatch b = events_.read_after(after, 512, std::chrono::milliseconds(wait_ms));
      json list = json::array();
      std::uint64_t last = after;
      for (const auto& e : b.events) {
        last = e.seq;
        if (job != 0 && e.job_id != job && e.job_id != 0) continue;
        json j = e.data.is_object() ? e.data : json::object();
        j["seq"] = e.seq;
        j["type"] = e.type;
        j["job_id"] = e.job_id;
        j["time_ms"] = e.time_ms;
        list.push_back(std::move(j));
      }
      if (b.events.empty()) last = std::max(after, events_.last_seq());
      return json{{"events", list}, {"last", last}, {"gap", b.gap}};
    };
    h.cancel_running = [this](std::int64_t id) {
      std::lock_guard lock(mu_);
      if (running_id_ == id && running_cancel_) running_cancel_->cancel();
    };
    h.cancelled_queued = [this, &store](std::int64_t id) {
      publish_job(id, JobState::kCancelled, "cancelled before it ran");
      if (auto rec = store.get(id); rec && *rec) finish_files(**rec, JobState::kCancelled, "cancelled before it ran");
    };
    return h;
  }

  Result<json> submit(JobStore& store, const fs::path& package, bool reprint) {
    auto checked = check_package(package, spool_dir(), cfg_.limits, check_job_stitches);
    if (!checked) return std::unexpected(checked.error());
    // One submit at a time between the duplicate check and the insert.
    std::lock_guard lock(submit_mu_);
    if (!reprint) {
      auto dup = store.find_live_by_hash(checked->content_hash);
      if (!dup) return std::unexpected(dup.error());
      if (*dup)
        return json{{"id", (*dup)->id}, {"name", printable_utf8((*dup)->name)}, {"duplicate", true},
                    {"state", std::string(to_string((*dup)->state))}};
    }
    auto id = enqueue(store, *checked, false, "socket");
    if (!id) return std::unexpected(id.error());
    return json{{"id", *id}, {"name", checked->job_name}, {"duplicate", false}, {"state", "queued"}};
  }

  // Queues a checked package: copies or moves it into the spool under a name no other job has.
  Result<std::int64_t> enqueue(JobStore& store, const CheckedPackage& pkg, bool move, const std::string& origin) {
    fs::path spooled;
    {
      std::lock_guard lock(spool_mu_);
      spooled = unique_child(spool_dir(), pkg.content_hash.substr(0, 12) + "-" + pkg.job_name +
                                              (fs::is_directory(pkg.path) ? "" : pkg.path.extension().string()));
      if (auto st = transfer_tree(pkg.path, spooled, move); !st) return std::unexpected(st.error());
    }
    make_private(spooled);
    keep_package(spooled, pkg.content_hash);
    fs::path out;
    {
      std::lock_guard lock(spool_mu_);
      out = unique_child(cfg_.out_dir, pkg.job_name);
      std::error_code ec;
      fs::create_directories(out, ec);  // claims the name before another job takes it
    }
    auto id = store.enqueue(pkg.job_name, spooled.string(), out.string(), origin, pkg.content_hash);
    if (!id) {
      remove_spooled(spooled);
      return id;
    }
    spdlog::info("printd: job {} '{}' queued from {}", *id, pkg.job_name, printable_utf8(origin));
    publish_job(*id, JobState::kQueued);
    wake_.notify_all();
    return id;
  }

  // A copy of an accepted package under its content hash (once per content), for reprints.
  void keep_package(const fs::path& spooled, const std::string& hash) {
    if (hash.empty()) return;
    const fs::path kept = packages_dir() / (hash + (fs::is_directory(spooled) ? "" : ".zip"));
    std::error_code ec;
    std::lock_guard lock(spool_mu_);
    if (fs::exists(kept, ec)) return;
    if (auto st = transfer_tree(spooled, kept, false); !st) {
      spdlog::warn("printd: cannot keep package for reprints: {}", st.error().message);
      return;
    }
    make_private(kept);
  }

  void take_from_hot_folder(JobStore& store, const HotFolder& hot, const fs::path& entry) {
    const std::string name = entry.filename().string();
    auto checked = check_package(entry, spool_dir(), cfg_.limits, check_job_stitches);
    if (!checked) {
      spdlog::warn("printd: {} refused: {}", printable_utf8(name), checked.error().message);
      fs::path dest = unique_child(hot.failed_dir(), name);
      if (transfer_tree(entry, dest / entry.filename(), true)) write_error_txt(dest / "error.txt", checked.error().message);
      return;
    }
    if (auto id = enqueue(store, *checked, true, kHotOrigin + name); !id)
      spdlog::error("printd: {}: {}", printable_utf8(entry.string()), id.error().message);
  }

  // The worker: one job at a time, since there is one printer.
  void work() {
    auto store = JobStore::open(db_path());
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
      running_stage_.clear();
      running_swath_ = rec.last_acked_swath;
      ++jobs_run_;
    }
    publish_job(rec.id, JobState::kRunning);
    set_crash_guard_job(rec.id);
    spdlog::info("printd: job {} '{}' running{}", rec.id, printable_utf8(rec.name),
                 rec.last_acked_swath >= 0 ? " (resuming after swath " + std::to_string(rec.last_acked_swath) + ")" : "");
    Status result = {};
    auto job = open_spooled_job(rec.package, cfg_.limits);
    if (!job) {
      result = std::unexpected(job.error());
    } else if (auto st = reserve_report(rec.out_dir, rec.name, rec.id); !st) {
      result = std::unexpected(st.error());
    } else {
      // The printer this job is planned for; the print stage checks the device's own ID against it.
      {
        auto m = job_printer_model(*job);
        std::lock_guard lock(mu_);
        printer_model_ = m ? m->name : std::string();
        printer_ieee1284_ = m ? m->ieee1284_id : std::string();
      }
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
        {
          std::lock_guard lock(mu_);
          running_stage_ = std::string(to_string(s));
        }
        json data = {{"stage", std::string(to_string(s))}, {"state", std::string(to_string(st))}, {"seconds", secs}};
        if (st == StageState::kRunning) data["fraction"] = 0.0;
        if (st == StageState::kDone || st == StageState::kReused || st == StageState::kSkipped) data["fraction"] = 1.0;
        events_.publish("progress", rec.id, std::move(data));
        // The cancel request may come from another printctl process, through the database.
        if (auto r = store.get(rec.id); r && *r && (*r)->cancel_requested) cancel.cancel();
      };
      opt.on_progress = [&](Stage s, double fraction, const std::string& detail) {
        events_.publish("progress", rec.id, json{{"stage", std::string(to_string(s))}, {"state", "running"},
                                                 {"fraction", fraction}, {"detail", detail}});
      };
      // The live printer: served by GET /api/v1/printer, and a `printer` event on each change.
      opt.on_printer = [&](const PrinterLive& live) {
        if (auto data = printer_view_.update(live)) events_.publish("printer", rec.id, std::move(*data));
      };
      opt.on_checkpoint = [&](std::int64_t swath) {
        (void)store.set_checkpoint(rec.id, swath);
        {
          std::lock_guard lock(mu_);
          running_swath_ = swath;
          ++swaths_acked_;
        }
        if (auto r = store.get(rec.id); r && *r && (*r)->cancel_requested) cancel.cancel();
      };
      try {
        result = run_job(*job, opt, cancel);
      } catch (const std::exception& e) {
        // A broken invariant inside the pipeline fails this job, not the daemon.
        result = fail(ErrorCode::kPipeline, std::string("internal error: ") + e.what());
      }
    }
    set_crash_guard_job(0);
    {
      std::lock_guard lock(mu_);
      running_id_ = 0;
      running_cancel_.reset();
    }
    // Stopping the daemon interrupts the job; it is queued again and resumes at the next start.
    if (stop_.load() && !result && result.error().code == ErrorCode::kCancelled) {
      (void)store.release(rec.id);
      publish_job(rec.id, JobState::kQueued, "interrupted by shutdown; resumes at the next start");
      spdlog::info("printd: job {} interrupted by shutdown", rec.id);
      return;
    }
    JobState final_state = result ? JobState::kDone
                                  : result.error().code == ErrorCode::kCancelled ? JobState::kCancelled
                                                                                 : JobState::kFailed;
    std::string error = result ? std::string() : result.error().message;
    (void)store.set_state(rec.id, final_state, error);
    publish_job(rec.id, final_state, error);
    if (result) spdlog::info("printd: job {} '{}' done", rec.id, printable_utf8(rec.name));
    else spdlog::warn("printd: job {} '{}' {}: {}", rec.id, printable_utf8(rec.name), to_string(final_state), error);
    finish_files(rec, final_state, error);
  }

  // A job has ended: report.json says how, the hot-folder entry goes back under done/ or
  // failed/, and the spooled copy is removed.
  void finish_files(const JobRecord& rec, JobState state, const std::string& error) {
    if (state != JobState::kDone) {
      if (auto st = ensure_failure_report(rec.out_dir, rec.name, rec.id, std::string(to_string(state)), error); !st)
        spdlog::error("printd: job {}: {}", rec.id, st.error().message);
    }
    if (!cfg_.hot_folder.empty() && rec.origin.rfind(kHotOrigin, 0) == 0) {
      const std::string entry = rec.origin.substr(kHotOrigin.size());
      fs::path dest = unique_child(cfg_.hot_folder / (state == JobState::kDone ? "done" : "failed"), entry);
      if (transfer_tree(rec.package, dest / entry, true)) {
        std::error_code ec;
        fs::copy_file(fs::path(rec.out_dir) / "report.json", dest / "report.json", ec);
        if (!error.empty()) write_error_txt(dest / "error.txt", error);
      }
    }
    remove_spooled(rec.package);
  }

  const DaemonConfig& cfg_;
  const std::atomic<bool>& stop_;
  std::mutex mu_;
  std::mutex submit_mu_;
  std::mutex spool_mu_;
  std::condition_variable wake_;
  std::int64_t running_id_ = 0;
  std::optional<geometry::CancelToken> running_cancel_;
  std::string running_stage_;
  std::string printer_model_;      ///< of the last job run (job_printer_model)
  std::string printer_ieee1284_;
  std::int64_t running_swath_ = -1;
  std::int64_t jobs_run_ = 0;
  std::int64_t swaths_acked_ = 0;
  EventLog events_;
  PrinterView printer_view_;
};

}  // namespace

Status run_daemon(const DaemonConfig& config, const std::atomic<bool>& stop) {
  Daemon d(config, stop);
  return d.run();
}

}  // namespace tp::host
