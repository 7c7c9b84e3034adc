// host/job/package.h: a job package on disk: a folder, or a .zip unpacked safely into a folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "host/common/error.h"

namespace tp::host {

/// Limits against decompression bombs and hostile archives.
struct PackageLimits {
  std::uint64_t max_total_bytes = 4ull << 30;   ///< all entries, uncompressed
  std::uint64_t max_entry_bytes = 2ull << 30;   ///< one entry, uncompressed
  double max_ratio = 250.0;                     ///< uncompressed / compressed, per entry and overall
  std::uint32_t max_entries = 10000;
};

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

  /// Resolves an asset path written in the manifest at JSON pointer `pointer`: it must be
  /// relative, without "..", stay inside the package after following symlinks, and name an
  /// existing regular file.
  [[nodiscard]] Result<std::filesystem::path> resolve_asset(const std::string& relative,
                                                            const std::string& pointer) const;

 private:
  std::filesystem::path source_;
  std::filesystem::path root_;
};

/// Checks one relative path as written in a manifest or an archive (no I/O): not empty, not
/// absolute, no ".." component, no NUL or backslash. Returns the reason when it is unsafe.
[[nodiscard]] Status check_relative_path(const std::string& relative);

/// Unpacks a zip archive into `dest` under `limits` (used by JobPackage::open).
[[nodiscard]] Status unpack_zip(const std::filesystem::path& zip, const std::filesystem::path& dest,
                                const PackageLimits& limits);

}  // namespace tp::host
