// host/store/job_store.h: the daemon's persistent job queue and per-job stage states (SQLite).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/common/error.h"

struct sqlite3;

namespace tp::host {

enum class JobState { kQueued, kRunning, kDone, kFailed, kCancelled };
std::string_view to_string(JobState s);
std::optional<JobState> job_state_from_string(std::string_view s);

/// One job as the store knows it.
struct JobRecord {
  std::int64_t id = 0;
  std::string name;
  std::string package;               ///< spooled package path (folder or zip) owned by the daemon
  std::string out_dir;               ///< where its outputs go
  std::string origin;                ///< where it came from: "hot-folder:<path>", "socket", "cli"
  JobState state = JobState::kQueued;
  std::string stage;                 ///< current or last pipeline stage
  std::string error;                 ///< why it failed
  std::int64_t submitted_ms = 0;     ///< Unix time, ms
  std::int64_t updated_ms = 0;
  std::int64_t last_acked_swath = -1;  ///< print checkpoint: highest swath the printer acknowledged
  bool cancel_requested = false;
  std::string content_hash;          ///< SHA-256 of the package as submitted (idempotent submit)
  int crash_count = 0;               ///< times printd died of a fatal signal while running it
  int unclean_exits = 0;             ///< times printd vanished (kill -9, power loss) while running it
};

/// What requeue_interrupted did at start-up.
struct RequeueResult {
  int requeued = 0;                  ///< back to "queued", resuming from their checkpoints
  int failed = 0;                    ///< over the unclean-exit limit: marked failed, not retried
};

/// Stage state of one job (PrusaSlicer's PrintState idea: one home for progress and resume).
struct StageRecord {
  std::string stage;
  std::string state;                 ///< "fresh", "running", "done", "failed", "cancelled"
  double seconds = 0;
};

/// A SQLite-backed job store. One instance per thread (connections are not shared).
class JobStore {
 public:
  JobStore(JobStore&&) noexcept;
  JobStore& operator=(JobStore&&) noexcept;
  ~JobStore();

  /// Opens or creates the database file (WAL mode, schema migrated).
  [[nodiscard]] static Result<JobStore> open(const std::filesystem::path& db_path);

  [[nodiscard]] Result<std::int64_t> enqueue(const std::string& name, const std::string& package,
                                             const std::string& out_dir, const std::string& origin,
                                             const std::string& content_hash = {});
  /// The newest job with this content hash that is queued, running or done (a retry of the same
  /// submit finds it and does not print twice), or nullopt.
  [[nodiscard]] Result<std::optional<JobRecord>> find_live_by_hash(const std::string& content_hash);
  /// Changes where a job's spooled package lives (after it was moved into the spool).
  [[nodiscard]] Status set_package(std::int64_t id, const std::string& package);
  /// Atomically takes the oldest queued job and marks it running.
  [[nodiscard]] Result<std::optional<JobRecord>> claim_next();
  [[nodiscard]] Result<std::optional<JobRecord>> get(std::int64_t id);
  /// Newest first.
  [[nodiscard]] Result<std::vector<JobRecord>> list(int limit);
  /// Newest first, `offset` jobs skipped, only jobs in `state` when it is given (HTTP paging).
  [[nodiscard]] Result<std::vector<JobRecord>> list_page(int limit, std::int64_t offset,
                                                         std::optional<JobState> state);
  /// How many jobs there are (in `state` when given).
  [[nodiscard]] Result<std::int64_t> count(std::optional<JobState> state);
  [[nodiscard]] Status set_state(std::int64_t id, JobState state, const std::string& error = {});
  [[nodiscard]] Status set_stage(std::int64_t id, const std::string& stage, const std::string& state,
                                 double seconds);
  [[nodiscard]] Result<std::vector<StageRecord>> stages(std::int64_t id);
  [[nodiscard]] Status set_checkpoint(std::int64_t id, std::int64_t last_acked_swath);
  /// The job's plan directory (garment, marker, swath plan; docs/plan-storage.md).
  [[nodiscard]] Status set_plan_dir(std::int64_t id, const std::string& plan_dir);
  /// nullopt when none was recorded.
  [[nodiscard]] Result<std::optional<std::string>> plan_dir(std::int64_t id);
  /// Queued jobs become cancelled at once; a running job gets cancel_requested for its worker.
  /// Fails with kJob if the job does not exist or has already ended.
  [[nodiscard]] Result<JobState> request_cancel(std::int64_t id);
  /// A job the daemon stopped cleanly (shutdown) goes back to "queued" with its checkpoint.
  [[nodiscard]] Status release(std::int64_t id);
  /// printd died of a fatal signal while running job `id` (its crash marker says so): counts the
  /// crash; at `max_crashes` the job is marked failed with `reason`, else it is queued again.
  /// Returns the job's state afterwards.
  [[nodiscard]] Result<JobState> record_crash(std::int64_t id, const std::string& reason, int max_crashes);
  /// After printd vanished (kill -9, power loss): jobs left "running" count an unclean exit and go
  /// back to "queued" with their checkpoint, unless they have now vanished more than
  /// `max_unclean_exits` times, which marks them failed (a crash loop). Cancel requests made
  /// before the restart make them cancelled.
  [[nodiscard]] Result<RequeueResult> requeue_interrupted(int max_unclean_exits = 8);

 private:
  explicit JobStore(sqlite3* db) : db_(db) {}
  [[nodiscard]] Status exec(const std::string& sql);
  sqlite3* db_ = nullptr;
};

}  // namespace tp::host
