// host/daemon/intake.h: validating a job package and taking it into the daemon's spool.
#pragma once

#include <filesystem>
#include <string>

#include "host/common/error.h"
#include "host/job/job.h"

namespace tp::host {

/// A package checked well enough to queue: it opens and its manifest validates.
struct CheckedPackage {
  std::string job_name;
  std::filesystem::path path;   ///< the package (folder or .zip)
};

/// Opens and validates the package at `path` (a .zip is unpacked into a scratch folder under
/// `scratch_dir`, removed again). Fails with the validation error of the package.
[[nodiscard]] Result<CheckedPackage> check_package(const std::filesystem::path& path,
                                                   const std::filesystem::path& scratch_dir);

/// Opens a spooled package for running: a folder in place; a zip unpacked afresh into
/// `<package>.unpacked`. Returns the validated job.
[[nodiscard]] Result<Job> open_spooled_job(const std::filesystem::path& package);

/// Copies (`move` = false) or moves a file or folder tree, across filesystems if needed.
[[nodiscard]] Status transfer_tree(const std::filesystem::path& from, const std::filesystem::path& to, bool move);

/// A name not yet used in `dir`: `base`, else `base-2`, `base-3`...
std::filesystem::path unique_child(const std::filesystem::path& dir, const std::string& base);

}  // namespace tp::host
