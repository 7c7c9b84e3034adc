// host/job/package.h: a job package on disk: a folder, or a .zip unpacked safely into a folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "host/common/error.h"

namespace tp::host {

/// Limits on what a job package may hold or ask for: against decompression bombs, hostile
/// archives and jobs that would exhaust the machine. Each has a name (the key of
/// `--limit NAME=VALUE` on printd and printctl run/validate; docs/daemon.md lists them) that a
/// refusal quotes with the limit.
struct PackageLimits {
  std::uint64_t max_total_bytes = 4ull << 30;   ///< max_zip_bytes: all entries, uncompressed
  std::uint64_t max_entry_bytes = 2ull << 30;   ///< max_zip_entry_bytes: one entry, uncompressed
  double max_ratio = 250.0;                     ///< max_zip_ratio: uncompressed / compressed
  std::uint32_t max_entries = 10000;            ///< max_zip_entries
  std::uint64_t max_manifest_bytes = 16u << 20; ///< max_manifest_bytes: job.json, checked before reading
  std::uint64_t max_asset_bytes = 1ull << 30;   ///< max_asset_bytes: one asset file (pattern, image, mesh)
  std::uint64_t max_design_layers = 32;         ///< max_layers: design layers in one job
  std::uint64_t max_stroke_points = 20000;      ///< max_stroke_points: points of one stroke
  std::uint64_t max_source_pixels = 1ull << 28; ///< max_source_pixels: all layers' source images together
  std::uint64_t max_memory_bytes = 4ull << 30;  ///< max_memory_bytes: estimated memory the design needs
};

/// Sets one limit from "NAME=VALUE" (NAME as in PackageLimits' comments). Fails naming the
/// known names when NAME is unknown or VALUE is not a positive number.
[[nodiscard]] Status set_limit(PackageLimits& limits, const std::string& name_equals_value);

/// "name=value" of every limit, for `--help` and docs.
std::string describe_limits(const PackageLimits& limits);

/// An opened package whose assets can be resolved safely.
class JobPackage {
 public:
  /// Opens `path`: a folder is used in place; a .zip is checked and unpacked into `unpack_dir`
  /// (created; must not exist or be empty). Fails naming the entry on an unsafe path (absolute,
  /// "..", symlink), an entry or total over the limits, or a suspicious compression ratio.
  [[nodiscard]] static Result<JobPackage> open(const std::filesystem::path& path,
                                               const std::filesystem::path& unpack_dir,
                                               const PackageLimits& limits = {});

  /// Folder holding job.json.
  const std::filesystem::path& root() const { return root_; }
  /// The path the user gave (folder or zip), for messages.
  const std::filesystem::path& source() const { return source_; }
  /// The limits it was opened with (assets and the design are checked against them too).
  const PackageLimits& limits() const { return limits_; }

  /// Resolves an asset path written in the manifest at JSON pointer `pointer`: it must be
  /// relative, without "..", stay inside the package after following symlinks, and name an
  /// existing regular file no larger than limits().max_asset_bytes.
  [[nodiscard]] Result<std::filesystem::path> resolve_asset(const std::string& relative,
                                                            const std::string& pointer) const;

 private:
  std::filesystem::path source_;
  std::filesystem::path root_;
  PackageLimits limits_;
};

/// Checks one relative path as written in a manifest or an archive (no I/O): not empty, not
/// absolute, no ".." component, no NUL or backslash. Returns the reason when it is unsafe.
[[nodiscard]] Status check_relative_path(const std::string& relative);

/// Unpacks a zip archive into `dest` under `limits` (used by JobPackage::open).
[[nodiscard]] Status unpack_zip(const std::filesystem::path& zip, const std::filesystem::path& dest,
                                const PackageLimits& limits);

}  // namespace tp::host
