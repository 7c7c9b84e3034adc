// host/daemon/intake.h: validating a job package and taking it into the daemon's spool.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "host/common/error.h"
#include "host/job/job.h"
#include "host/job/package.h"

namespace tp::host {

/// A package checked well enough to queue: it opens and its manifest validates.
struct CheckedPackage {
  std::string job_name;
  std::filesystem::path path;   ///< the package (folder or .zip)
  std::string content_hash;     ///< SHA-256 of the package (sha256.h), for idempotent submit
};

/// A further check of a validated job while its package's files are at hand (the daemon's:
/// check_job_stitches, host/pipeline/job_stitch_check.h).
using JobCheck = std::function<Status(const Job&)>;

/// Opens and validates the package at `path` (a .zip is unpacked into a scratch folder under
/// `scratch_dir`, removed again), then runs `check` on the job if given. Fails with the
/// validation error of the package. Everything is checked against `limits`; the refusal names
/// the limit that was crossed.
[[nodiscard]] Result<CheckedPackage> check_package(const std::filesystem::path& path,
                                                   const std::filesystem::path& scratch_dir,
                                                   const PackageLimits& limits = {}, const JobCheck& check = {});

/// Opens a spooled package for running: a folder in place; a zip unpacked afresh into
/// `<package>.unpacked`. Returns the validated job.
[[nodiscard]] Result<Job> open_spooled_job(const std::filesystem::path& package, const PackageLimits& limits = {});

/// Removes a spooled package and its unpacked copy (when its job has ended).
void remove_spooled(const std::filesystem::path& package);

/// Makes a tree private to the daemon's user: folders 0700, files 0600.
void make_private(const std::filesystem::path& path);

/// Copies (`move` = false) or moves a file or folder tree, across filesystems if needed.
[[nodiscard]] Status transfer_tree(const std::filesystem::path& from, const std::filesystem::path& to, bool move);

/// A name not yet used in `dir`: `base`, else `base-2`, `base-3`... inserted before the
/// extension of a file name ("job.zip" -> "job-2.zip"), so the spooled copy stays a .zip.
std::filesystem::path unique_child(const std::filesystem::path& dir, const std::string& base);

}  // namespace tp::host
