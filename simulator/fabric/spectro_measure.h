// simulator/fabric/spectro_measure.h: the simulated spectrophotometer: reads the patches of a
// chart off the virtual fabric's CIELAB image (fabric-lab.tif) through a round aperture, with
// optional seeded measurement noise, and writes CGATS .ti3 measurements (ArgyllCMS).
#pragma once

#include <cstdint>
#include <filesystem>

#include "simulator/common/error.h"

namespace tp::sim {

struct MeasureOptions {
  std::filesystem::path chart;          ///< chart layout (CGATS; docs/colour.md, "Chart layout")
  std::filesystem::path fabric_lab;     ///< the printed fabric's fabric-lab.tif
  std::filesystem::path out_ti3;        ///< measurements written here
  double aperture_mm = 4;               ///< diameter of the measured spot
  double noise_de = 0;                  ///< standard deviation of noise added per L*, a*, b*
  std::uint64_t seed = 1;               ///< noise seed (the same seed repeats a reading)
};

struct MeasureSummary {
  std::size_t patches = 0;
  double min_samples = 0;               ///< fewest preview pixels inside the aperture of a patch
};

/// Measures every patch of the chart. Fails with kInvalidArgument naming the file and patch for
/// a chart without the needed fields, a patch whose aperture leaves the image, or an unreadable
/// image; kOutput if the .ti3 cannot be written.
[[nodiscard]] Result<MeasureSummary> measure_chart(const MeasureOptions& options);

}  // namespace tp::sim
