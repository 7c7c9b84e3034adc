// host/calibration/chart_layout.h: a profiling chart's picture: the patches of an ArgyllCMS
// .ti1 (RGB) in a grid inside a black frame with an orientation mark, and each patch's centre.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "device/model/cgats.h"
#include "geometry/common/image.h"
#include "host/common/error.h"

namespace tp::host {

struct ChartGeometry {
  double patch_mm = 8;
  int columns = 30;
  double frame_mm = 3;      ///< black frame around everything
  double gap_mm = 3;        ///< white between frame and patches
  double px_per_mm = 5;     ///< picture resolution (flat colours: any will do)
};

struct ChartLayout {
  ChartGeometry geometry;
  double width_mm = 0, height_mm = 0;   ///< outer size, frame included
  geometry::ImageRgba8 image;
  struct Patch {
    std::string id;
    std::array<double, 3> rgb_pct{};    ///< device values as the .ti1 gives them, 0..100
    double x_mm = 0, y_mm = 0;          ///< centre from the chart's top-left corner
  };
  std::vector<Patch> patches;
  /// Centre of the orientation mark (a black square in the gap at the top-left corner).
  double mark_x_mm = 0, mark_y_mm = 0;
};

/// Lays out the patches of `ti1` (fields SAMPLE_ID, RGB_R, RGB_G, RGB_B). Fails with kValidation
/// naming `source` if a field is missing or a value is outside 0..100.
[[nodiscard]] Result<ChartLayout> layout_chart(const device::CgatsTable& ti1, const std::string& source,
                                               const ChartGeometry& geometry = {});

}  // namespace tp::host
