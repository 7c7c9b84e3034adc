// host/daemon/studio/studio_preview.h: the studio's live preview: a design rendered on a studio
// garment by the product's own piece renderer into the atlas its mesh's UVs point into.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host/daemon/studio/studio_garment.h"

namespace tp::host {

/// A rendered preview atlas.
struct StudioPreview {
  std::string png;       ///< the atlas (RGB over white fabric), same size and layout as the garment's
  double parse_ms = 0;   ///< job.json written and validated
  double build_ms = 0;   ///< design stage: layers read, renderer built
  double render_ms = 0;  ///< every piece rendered into the atlas
  double encode_ms = 0;  ///< the atlas packed as PNG
};

/// Renders `design` (job.json's "design" object: {"layers": [...]}) on `g` at the atlas dpi.
/// Fails (kValidation) with job.json pointer lines for a design the validator refuses, or with
/// the design stage's error. A newer call for the same garment supersedes this one: it stops
/// between build runs or render bands and fails with kCancelled ("superseded"), as it does when
/// `cancel` fires. Takes g.mu.
[[nodiscard]] Result<StudioPreview> render_studio_preview(StudioGarment& g, const nlohmann::json& design,
                                                          const PackageLimits& limits,
                                                          const geometry::CancelToken& cancel);

}  // namespace tp::host
