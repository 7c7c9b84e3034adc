// host/job/manifest.h: reading and validating a package's job.json (format in docs/job-format.md).
#pragma once

#include <string>

#include "host/common/error.h"
#include "host/job/job.h"
#include "host/job/package.h"

namespace tp::host {

/// The manifest format this host reads.
inline constexpr const char* kJobFormat = "tp-job/1";

/// Reads and validates `job.json` of an opened package. On failure the error (code kValidation
/// or kUnsafePath) lists every problem found, one per line, each as
/// "job.json: <JSON pointer>: <what is wrong>".
[[nodiscard]] Result<Job> load_job(const JobPackage& package);

/// Same, from manifest text (for tests and fuzzing); assets resolve against `package`.
[[nodiscard]] Result<Job> parse_job(const std::string& manifest_text, const JobPackage* package);

}  // namespace tp::host
