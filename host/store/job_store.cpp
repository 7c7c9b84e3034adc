// host/store/job_store.cpp: SQLite schema and statements behind the job store.
#include "host/store/job_store.h"

#include <sqlite3.h>

#include <chrono>
#include <utility>

namespace tp::host {

namespace {

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// RAII prepared statement with typed binding.
class Stmt {
 public:
  Stmt(sqlite3* db, const char* sql) : db_(db) { rc_ = sqlite3_prepare_v2(db, sql, -1, &st_, nullptr); }
  ~Stmt() { sqlite3_finalize(st_); }
  Stmt(const Stmt&) = delete;
  Stmt& operator=(const Stmt&) = delete;
  bool ok() const { return rc_ == SQLITE_OK; }
  void bind(int i, std::int64_t v) { sqlite3_bind_int64(st_, i, v); }
  void bind(int i, double v) { sqlite3_bind_double(st_, i, v); }
  void bind(int i, const std::string& v) { sqlite3_bind_text(st_, i, v.c_str(), -1, SQLITE_TRANSIENT); }
  int step() { return sqlite3_step(st_); }
  std::int64_t i64(int c) const { return sqlite3_column_int64(st_, c); }
  double f64(int c) const { return sqlite3_column_double(st_, c); }
  std::string text(int c) const {
    const unsigned char* t = sqlite3_column_text(st_, c);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  std::string error() const { return sqlite3_errmsg(db_); }

 private:
  sqlite3* db_;
  sqlite3_stmt* st_ = nullptr;
  int rc_;
};

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS jobs (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  name TEXT NOT NULL,
  package TEXT NOT NULL,
  out_dir TEXT NOT NULL,
  origin TEXT NOT NULL DEFAULT '',
  state TEXT NOT NULL,
  stage TEXT NOT NULL DEFAULT '',
  error TEXT NOT NULL DEFAULT '',
  submitted_ms INTEGER NOT NULL,
  updated_ms INTEGER NOT NULL,
  last_acked_swath INTEGER NOT NULL DEFAULT -1,
  cancel_requested INTEGER NOT NULL DEFAULT 0
);
CREATE INDEX IF NOT EXISTS jobs_state ON jobs(state, id);
CREATE TABLE IF NOT EXISTS job_stages (
  job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
  stage TEXT NOT NULL,
  state TEXT NOT NULL,
  seconds REAL NOT NULL DEFAULT 0,
  PRIMARY KEY (job_id, stage)
);
CREATE TABLE IF NOT EXISTS job_plans (
  job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
  plan_dir TEXT NOT NULL
);
PRAGMA user_version = 1;
)sql";

// Columns added after the first schema: added in place to an older database on open.
constexpr const char* kAddedColumns[][2] = {
    {"content_hash", "TEXT NOT NULL DEFAULT ''"},
    {"crash_count", "INTEGER NOT NULL DEFAULT 0"},
    {"unclean_exits", "INTEGER NOT NULL DEFAULT 0"},
};

constexpr const char* kColumns =
    "id, name, package, out_dir, origin, state, stage, error, submitted_ms, updated_ms, last_acked_swath, "
    "cancel_requested, content_hash, crash_count, unclean_exits";

JobRecord read_record(const Stmt& s) {
  JobRecord r;
  r.id = s.i64(0);
  r.name = s.text(1);
  r.package = s.text(2);
  r.out_dir = s.text(3);
  r.origin = s.text(4);
  r.state = job_state_from_string(s.text(5)).value_or(JobState::kFailed);
  r.stage = s.text(6);
  r.error = s.text(7);
  r.submitted_ms = s.i64(8);
  r.updated_ms = s.i64(9);
  r.last_acked_swath = s.i64(10);
  r.cancel_requested = s.i64(11) != 0;
  r.content_hash = s.text(12);
  r.crash_count = static_cast<int>(s.i64(13));
  r.unclean_exits = static_cast<int>(s.i64(14));
  return r;
}

}  // namespace

std::string_view to_string(JobState s) {
  switch (s) {
    case JobState::kQueued: return "queued";
    case JobState::kRunning: return "running";
    case JobState::kDone: return "done";
    case JobState::kFailed: return "failed";
    case JobState::kCancelled: return "cancelled";
  }
  return "unknown";
}

std::optional<JobState> job_state_from_string(std::string_view s) {
  for (JobState st : {JobState::kQueued, JobState::kRunning, JobState::kDone, JobState::kFailed, JobState::kCancelled})
    if (to_string(st) == s) return st;
  return std::nullopt;
}

JobStore::JobStore(JobStore&& o) noexcept : db_(std::exchange(o.db_, nullptr)) {}
JobStore& JobStore::operator=(JobStore&& o) noexcept {
  if (this != &o) {
    if (db_) sqlite3_close(db_);
    db_ = std::exchange(o.db_, nullptr);
  }
  return *this;
}
JobStore::~JobStore() {
  if (db_) sqlite3_close(db_);
}

Status JobStore::exec(const std::string& sql) {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    return fail(ErrorCode::kStore, "job store: " + msg);
  }
  return {};
}

Result<JobStore> JobStore::open(const std::filesystem::path& db_path) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    std::string msg = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    return fail(ErrorCode::kStore, db_path.string() + ": cannot open job store: " + msg);
  }
  JobStore store(db);
  // The daemon and printctl may touch the file at once; wait rather than fail on a lock.
  sqlite3_busy_timeout(db, 5000);
  if (auto st = store.exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL; PRAGMA foreign_keys=ON;"); !st)
    return std::unexpected(st.error().with_context(db_path.string()));
  if (auto st = store.exec(kSchema); !st) return std::unexpected(st.error().with_context(db_path.string()));
  for (const auto& [name, type] : kAddedColumns) {
    Stmt probe(db, "SELECT 1 FROM pragma_table_info('jobs') WHERE name=?");
    probe.bind(1, std::string(name));
    if (probe.step() == SQLITE_ROW) continue;
    if (auto st = store.exec(std::string("ALTER TABLE jobs ADD COLUMN ") + name + " " + type); !st)
      return std::unexpected(st.error().with_context(db_path.string()));
  }
  return store;
}

Result<std::int64_t> JobStore::enqueue(const std::string& name, const std::string& package,
                                       const std::string& out_dir, const std::string& origin,
                                       const std::string& content_hash) {
  Stmt s(db_, "INSERT INTO jobs(name, package, out_dir, origin, state, submitted_ms, updated_ms, content_hash) "
              "VALUES(?, ?, ?, ?, 'queued', ?, ?, ?)");
  if (!s.ok()) return fail(ErrorCode::kStore, "enqueue: " + s.error());
  std::int64_t t = now_ms();
  s.bind(1, name); s.bind(2, package); s.bind(3, out_dir); s.bind(4, origin); s.bind(5, t); s.bind(6, t);
  s.bind(7, content_hash);
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "enqueue '" + name + "': " + s.error());
  return sqlite3_last_insert_rowid(db_);
}

Result<std::optional<JobRecord>> JobStore::claim_next() {
  // One statement claims the job so two workers can never take the same one.
  std::string sql = std::string("UPDATE jobs SET state='running', updated_ms=? WHERE id = "
                                "(SELECT id FROM jobs WHERE state='queued' ORDER BY id LIMIT 1) RETURNING ") +
                    kColumns;
  Stmt s(db_, sql.c_str());
  if (!s.ok()) return fail(ErrorCode::kStore, "claim: " + s.error());
  s.bind(1, now_ms());
  int rc = s.step();
  if (rc == SQLITE_DONE) return std::optional<JobRecord>{};
  if (rc != SQLITE_ROW) return fail(ErrorCode::kStore, "claim: " + s.error());
  JobRecord r = read_record(s);
  while (s.step() == SQLITE_ROW) {}
  return std::optional<JobRecord>(std::move(r));
}

Result<std::optional<JobRecord>> JobStore::get(std::int64_t id) {
  std::string sql = std::string("SELECT ") + kColumns + " FROM jobs WHERE id=?";
  Stmt s(db_, sql.c_str());
  if (!s.ok()) return fail(ErrorCode::kStore, "get: " + s.error());
  s.bind(1, id);
  int rc = s.step();
  if (rc == SQLITE_DONE) return std::optional<JobRecord>{};
  if (rc != SQLITE_ROW) return fail(ErrorCode::kStore, "get job " + std::to_string(id) + ": " + s.error());
  return std::optional<JobRecord>(read_record(s));
}

Result<std::vector<JobRecord>> JobStore::list(int limit) {
  std::string sql = std::string("SELECT ") + kColumns + " FROM jobs ORDER BY id DESC LIMIT ?";
  Stmt s(db_, sql.c_str());
  if (!s.ok()) return fail(ErrorCode::kStore, "list: " + s.error());
  s.bind(1, static_cast<std::int64_t>(limit));
  std::vector<JobRecord> out;
  int rc;
  while ((rc = s.step()) == SQLITE_ROW) out.push_back(read_record(s));
  if (rc != SQLITE_DONE) return fail(ErrorCode::kStore, "list: " + s.error());
  return out;
}

Result<std::vector<JobRecord>> JobStore::list_page(int limit, std::int64_t offset, std::optional<JobState> state) {
  std::string sql = std::string("SELECT ") + kColumns + " FROM jobs" + (state ? " WHERE state=?" : "") +
                    " ORDER BY id DESC LIMIT ? OFFSET ?";
  Stmt s(db_, sql.c_str());
  if (!s.ok()) return fail(ErrorCode::kStore, "list: " + s.error());
  int i = 1;
  if (state) s.bind(i++, std::string(to_string(*state)));
  s.bind(i++, static_cast<std::int64_t>(limit));
  s.bind(i++, offset);
  std::vector<JobRecord> out;
  int rc;
  while ((rc = s.step()) == SQLITE_ROW) out.push_back(read_record(s));
  if (rc != SQLITE_DONE) return fail(ErrorCode::kStore, "list: " + s.error());
  return out;
}

Result<std::int64_t> JobStore::count(std::optional<JobState> state) {
  Stmt s(db_, state ? "SELECT COUNT(*) FROM jobs WHERE state=?" : "SELECT COUNT(*) FROM jobs");
  if (!s.ok()) return fail(ErrorCode::kStore, "count: " + s.error());
  if (state) s.bind(1, std::string(to_string(*state)));
  if (s.step() != SQLITE_ROW) return fail(ErrorCode::kStore, "count: " + s.error());
  return s.i64(0);
}

Status JobStore::set_state(std::int64_t id, JobState state, const std::string& error) {
  Stmt s(db_, "UPDATE jobs SET state=?, error=?, updated_ms=? WHERE id=?");
  if (!s.ok()) return fail(ErrorCode::kStore, "set_state: " + s.error());
  s.bind(1, std::string(to_string(state))); s.bind(2, error); s.bind(3, now_ms()); s.bind(4, id);
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  return {};
}

Status JobStore::set_stage(std::int64_t id, const std::string& stage, const std::string& state, double seconds) {
  Stmt s(db_, "INSERT INTO job_stages(job_id, stage, state, seconds) VALUES(?, ?, ?, ?) "
              "ON CONFLICT(job_id, stage) DO UPDATE SET state=excluded.state, seconds=excluded.seconds");
  if (!s.ok()) return fail(ErrorCode::kStore, "set_stage: " + s.error());
  s.bind(1, id); s.bind(2, stage); s.bind(3, state); s.bind(4, seconds);
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  Stmt u(db_, "UPDATE jobs SET stage=?, updated_ms=? WHERE id=?");
  u.bind(1, stage); u.bind(2, now_ms()); u.bind(3, id);
  if (u.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + u.error());
  return {};
}

Result<std::vector<StageRecord>> JobStore::stages(std::int64_t id) {
  Stmt s(db_, "SELECT stage, state, seconds FROM job_stages WHERE job_id=? ORDER BY rowid");
  if (!s.ok()) return fail(ErrorCode::kStore, "stages: " + s.error());
  s.bind(1, id);
  std::vector<StageRecord> out;
  while (s.step() == SQLITE_ROW) out.push_back({s.text(0), s.text(1), s.f64(2)});
  return out;
}

Status JobStore::set_checkpoint(std::int64_t id, std::int64_t last_acked_swath) {
  Stmt s(db_, "UPDATE jobs SET last_acked_swath=?, updated_ms=? WHERE id=?");
  if (!s.ok()) return fail(ErrorCode::kStore, "set_checkpoint: " + s.error());
  s.bind(1, last_acked_swath); s.bind(2, now_ms()); s.bind(3, id);
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  return {};
}

Status JobStore::set_plan_dir(std::int64_t id, const std::string& plan_dir) {
  Stmt s(db_, "INSERT INTO job_plans (job_id, plan_dir) VALUES (?, ?) ON CONFLICT(job_id) DO UPDATE SET plan_dir=excluded.plan_dir");
  if (!s.ok()) return fail(ErrorCode::kStore, "set_plan_dir: " + s.error());
  s.bind(1, id); s.bind(2, plan_dir);
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  return {};
}

Result<std::optional<std::string>> JobStore::plan_dir(std::int64_t id) {
  Stmt s(db_, "SELECT plan_dir FROM job_plans WHERE job_id=?");
  if (!s.ok()) return fail(ErrorCode::kStore, "plan_dir: " + s.error());
  s.bind(1, id);
  const int rc = s.step();
  if (rc == SQLITE_DONE) return std::optional<std::string>{};
  if (rc != SQLITE_ROW) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  return std::optional<std::string>(s.text(0));
}

Result<JobState> JobStore::request_cancel(std::int64_t id) {
  auto rec = get(id);
  if (!rec) return std::unexpected(rec.error());
  if (!*rec) return fail(ErrorCode::kJob, "no job " + std::to_string(id));
  JobState st = (*rec)->state;
  if (st == JobState::kQueued) {
    // Guard on the state so a worker that claimed it meanwhile is not overruled.
    Stmt s(db_, "UPDATE jobs SET state='cancelled', updated_ms=? WHERE id=? AND state='queued'");
    s.bind(1, now_ms()); s.bind(2, id);
    s.step();
    if (sqlite3_changes(db_) == 1) return JobState::kCancelled;
    st = JobState::kRunning;
  }
  if (st == JobState::kRunning) {
    Stmt s(db_, "UPDATE jobs SET cancel_requested=1, updated_ms=? WHERE id=?");
    s.bind(1, now_ms()); s.bind(2, id);
    if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "cancel: " + s.error());
    return JobState::kRunning;
  }
  return fail(ErrorCode::kJob, "job " + std::to_string(id) + " has already ended (" + std::string(to_string(st)) + ")");
}

Result<std::optional<JobRecord>> JobStore::find_live_by_hash(const std::string& content_hash) {
  std::string sql = std::string("SELECT ") + kColumns +
                    " FROM jobs WHERE content_hash=? AND content_hash<>'' AND state IN ('queued','running','done') "
                    "ORDER BY id DESC LIMIT 1";
  Stmt s(db_, sql.c_str());
  if (!s.ok()) return fail(ErrorCode::kStore, "find by hash: " + s.error());
  s.bind(1, content_hash);
  int rc = s.step();
  if (rc == SQLITE_DONE) return std::optional<JobRecord>{};
  if (rc != SQLITE_ROW) return fail(ErrorCode::kStore, "find by hash: " + s.error());
  return std::optional<JobRecord>(read_record(s));
}

Status JobStore::set_package(std::int64_t id, const std::string& package) {
  Stmt s(db_, "UPDATE jobs SET package=?, updated_ms=? WHERE id=?");
  if (!s.ok()) return fail(ErrorCode::kStore, "set_package: " + s.error());
  s.bind(1, package); s.bind(2, now_ms()); s.bind(3, id);
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  return {};
}

Status JobStore::release(std::int64_t id) {
  Stmt s(db_, "UPDATE jobs SET state='queued', updated_ms=? WHERE id=? AND state='running'");
  if (!s.ok()) return fail(ErrorCode::kStore, "release: " + s.error());
  s.bind(1, now_ms()); s.bind(2, id);
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  return {};
}

Result<JobState> JobStore::record_crash(std::int64_t id, const std::string& reason, int max_crashes) {
  Stmt s(db_, "UPDATE jobs SET crash_count = crash_count + 1, updated_ms=?, "
              "state = CASE WHEN cancel_requested THEN 'cancelled' WHEN crash_count + 1 >= ? THEN 'failed' "
              "ELSE 'queued' END, "
              "error = CASE WHEN crash_count + 1 >= ? THEN ? ELSE error END "
              "WHERE id=? AND state IN ('running','queued') RETURNING state");
  if (!s.ok()) return fail(ErrorCode::kStore, "record_crash: " + s.error());
  s.bind(1, now_ms()); s.bind(2, static_cast<std::int64_t>(max_crashes)); s.bind(3, static_cast<std::int64_t>(max_crashes));
  s.bind(4, reason); s.bind(5, id);
  int rc = s.step();
  if (rc == SQLITE_DONE) return fail(ErrorCode::kJob, "job " + std::to_string(id) + " is not running");
  if (rc != SQLITE_ROW) return fail(ErrorCode::kStore, "job " + std::to_string(id) + ": " + s.error());
  auto st = job_state_from_string(s.text(0)).value_or(JobState::kFailed);
  while (s.step() == SQLITE_ROW) {}
  return st;
}

Result<RequeueResult> JobStore::requeue_interrupted(int max_unclean_exits) {
  RequeueResult out;
  // Each job printd was running when it vanished counts one unclean exit.
  Stmt count(db_, "UPDATE jobs SET unclean_exits = unclean_exits + 1 WHERE state='running' AND NOT cancel_requested");
  if (!count.ok() || count.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "requeue: " + count.error());
  Stmt loop(db_, "UPDATE jobs SET state='failed', updated_ms=?, error='printd stopped ' || unclean_exits || "
                 "' times while running this job (killed, out of memory or power lost); not retried again "
                 "(printd --max-unclean-exits=' || ? || ')' WHERE state='running' AND NOT cancel_requested "
                 "AND unclean_exits > ?");
  if (!loop.ok()) return fail(ErrorCode::kStore, "requeue: " + loop.error());
  loop.bind(1, now_ms()); loop.bind(2, static_cast<std::int64_t>(max_unclean_exits));
  loop.bind(3, static_cast<std::int64_t>(max_unclean_exits));
  if (loop.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "requeue: " + loop.error());
  out.failed = sqlite3_changes(db_);
  // A job whose cancel was asked for before the restart stays cancelled, not re-run.
  Stmt s(db_, "UPDATE jobs SET state = CASE WHEN cancel_requested THEN 'cancelled' ELSE 'queued' END, "
              "updated_ms=? WHERE state='running'");
  if (!s.ok()) return fail(ErrorCode::kStore, "requeue: " + s.error());
  s.bind(1, now_ms());
  if (s.step() != SQLITE_DONE) return fail(ErrorCode::kStore, "requeue: " + s.error());
  out.requeued = sqlite3_changes(db_);
  return out;
}

}  // namespace tp::host
