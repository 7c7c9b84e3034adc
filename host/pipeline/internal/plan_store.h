// host/pipeline/internal/plan_store.h: a job's plan directory: one file per plan step (garment,
// pieces, marker, swath plan) and plan.json, which records the inputs hash each was made from.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "host/common/error.h"

namespace tp::host::internal {

/// The plan of one job, kept in its state. A step's file is valid while the hash of the inputs
/// that step reads is the one recorded; the pipeline then loads it instead of computing it again.
class PlanStore {
 public:
  /// Opens (creating it, mode 0700) the plan directory `dir` and reads its plan.json. A missing
  /// index is an empty plan; an unreadable or corrupt one fails naming the file.
  [[nodiscard]] static Result<PlanStore> open(const std::filesystem::path& dir);

  const std::filesystem::path& dir() const { return dir_; }

  /// The stored file of `step` when it was made from inputs hashing to `inputs_hash` and still
  /// exists; nullopt otherwise (never made, or its inputs changed).
  [[nodiscard]] std::optional<std::filesystem::path> find(std::string_view step, std::string_view inputs_hash) const;

  /// Writes `bytes` as `file` (under a temporary name, then renamed) and records it for `step`
  /// with `inputs_hash` in plan.json (rewritten the same way). Fails (kIo) naming the path.
  [[nodiscard]] Status save(std::string_view step, std::string_view inputs_hash, const std::string& file,
                            const std::string& bytes);

  /// Reads a stored file whole. Fails (kIo) naming it.
  [[nodiscard]] static Result<std::string> read(const std::filesystem::path& path);

 private:
  std::filesystem::path dir_;
  nlohmann::json index_;
};

}  // namespace tp::host::internal
