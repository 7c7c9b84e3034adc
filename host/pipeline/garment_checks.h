// host/pipeline/garment_checks.h: the fit checks and the stitches used, as report.json and bench output.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "geometry/garment/fit_checks.h"
#include "geometry/pattern/pattern.h"
#include "host/job/job.h"

namespace tp::host {

/// The job's limits for geometry::check_fit.
geometry::FitLimits fit_limits(const GarmentChecksSpec& spec);

/// report.json `garment.checks`: the figures, the limits, "pass" and the failures (each with
/// the preview file `<preview_prefix><view>.png` to look at), and the pieces printed flat
/// because no stitch joins them to the garment (`unsewn_pieces`).
nlohmann::json checks_json(const geometry::Pattern& pattern, const geometry::FitReport& r, const geometry::FitLimits& limits,
                           const std::string& preview_prefix);

/// report.json `garment.stitches`: per stitch its two sides (piece and edge names, span in mm),
/// its source entry from `sources` (index-aligned; "pattern" when missing) and its gap at the
/// end of sewing (max, mm) when `gaps_mm` has it.
nlohmann::json stitches_json(const geometry::Pattern& pattern, const std::vector<nlohmann::json>& sources,
                             const std::vector<std::vector<double>>& gaps_mm);

/// The failures as one message: "garment checks failed: <failure> (look at <file>); ...".
std::string checks_failure_message(const geometry::FitReport& r, const std::string& preview_prefix);

}  // namespace tp::host
