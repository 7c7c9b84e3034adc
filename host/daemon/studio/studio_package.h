// host/daemon/studio/studio_package.h: a studio design saved as a job package: job.json (the
// garment as sewn in the studio, the design, finishing, marker and print settings) and every
// uploaded asset, zipped, checked by the same validator as `printctl validate`.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "host/daemon/studio/studio_garment.h"

namespace tp::host {

/// Writes `zip_path`: job.json from `settings` ({"name", "design", "finishing", "marker",
/// "print"}, each optional; marker.fabric_width defaults to 1.6 m) over the garment's section, and
/// the session's assets/ folder. The manifest is validated against the session before, and the
/// zip is opened and validated again after. Fails (kValidation) with job.json pointer lines.
/// Takes g.mu.
[[nodiscard]] Status write_studio_package(StudioGarment& g, const nlohmann::json& settings,
                                          const std::filesystem::path& zip_path, const PackageLimits& limits);

}  // namespace tp::host
