// host/pipeline/job_stitch_check.h: refusing, at validation, a job to be sewn on a body whose pattern has nothing to
// sew.
#pragma once

#include <string>

#include "host/common/error.h"
#include "host/job/job.h"

namespace tp::host {

/// What a job is told when its pattern, with the job's stitches file and suggestions
/// (`garment.stitches: "suggest"`), has no stitch although the job names a body.
[[nodiscard]] std::string no_stitches_message(const GarmentSpec& garment, const std::string& pattern_name);

/// For a job with a body and a pattern file: loads the pattern, adds the job's stitches file and,
/// with "suggest", the suggestions the pattern stage would add, and fails (kValidation, the
/// message above) when no stitch results, or with the pattern's or stitches file's own error.
/// Jobs without a body (printed flat), samples and OBJ garments pass unread. For printctl
/// validate and the daemon's intake, while the package's files are at hand.
[[nodiscard]] Status check_job_stitches(const Job& job);

}  // namespace tp::host
