// host/job/design_limits.h: the resource caps a validated job must stay under (layers, stroke
// points, source pixels, estimated memory), checked before any stage runs.
#pragma once

#include <cstdint>

#include "host/common/error.h"
#include "host/job/job.h"
#include "host/job/package.h"

namespace tp::host {

/// What the design asks of the machine, as counted by check_design_limits.
struct DesignCost {
  std::uint64_t layers = 0;
  std::uint64_t max_stroke_points = 0;
  std::uint64_t source_pixels = 0;     ///< procedural tiles (size_px²) plus PNG/JPEG images
  std::uint64_t estimated_bytes = 0;   ///< 4 B per source pixel (RGBA8) + 256 B per stroke point
};

/// Counts the design's cost (image sizes from their headers, nothing decoded).
DesignCost measure_design(const Job& job);

/// Fails (kValidation) with one line per cap exceeded, each naming the field, the figure, the
/// limit and the setting that raises it ("job.json: /design/layers/2/points: 200000 points, over
/// the limit of 20000 (max_stroke_points; raise it with --limit max_stroke_points=N)").
[[nodiscard]] Status check_design_limits(const Job& job, const PackageLimits& limits);

}  // namespace tp::host
