// simulator/printsim/fabric_journal.h: the swaths a job laid on the fabric, appended to a file as
// they print (printsim --state), so a printsim killed mid-job (a printer that lost power) starts
// again with the same physical fabric: the restarted recorder replays them onto its canvas.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <span>

#include "device/swath/swath.h"
#include "simulator/common/error.h"

namespace tp::sim {

class FabricJournal {
 public:
  /// Starts a journal for job `job_id` at `path` (replacing an older one).
  [[nodiscard]] static Result<FabricJournal> create(const std::filesystem::path& path, std::uint64_t job_id);
  /// Opens the journal at `path` to append to it, after calling `laid` for each swath recorded
  /// with an index below `before_swath` (records from there on are dropped: not on the fabric).
  /// Fails with kInvalidArgument if the file is missing, damaged or of another job.
  [[nodiscard]] static Result<FabricJournal> reopen(
      const std::filesystem::path& path, std::uint64_t job_id, std::uint32_t before_swath,
      const std::function<void(const device::SwathHeader&, std::span<const std::uint8_t>)>& laid);
  FabricJournal(FabricJournal&& other) noexcept;
  FabricJournal& operator=(FabricJournal&& other) noexcept;
  ~FabricJournal();

  /// Appends a printed swath (raw data as laid). Fails with kOutput naming the file.
  [[nodiscard]] Status append(const device::SwathHeader& header, std::span<const std::uint8_t> raw);
  /// Closes and deletes the file (the job ended: its fabric is written out).
  void discard();

 private:
  FabricJournal(std::FILE* f, std::filesystem::path path) : f_(f), path_(std::move(path)) {}
  std::FILE* f_ = nullptr;
  std::filesystem::path path_;
};

}  // namespace tp::sim
