// simulator/fabric/fabric_preview.h: the fabric's colour at the preview scale: box-averaged drop
// levels through the colorimetric printer, written as an sRGB PNG (media-relative: bare fabric is
// white) and a CIELAB (D50, absolute) float TIFF.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "simulator/common/error.h"
#include "simulator/fabric/fabric_colour.h"

namespace tp::sim {

struct PreviewSpec {
  std::uint32_t width_px = 0;   ///< fabric pixels across
  std::uint64_t height_px = 0;  ///< fabric rows
  int scale = 1;                ///< fabric pixels per preview pixel, each way
  int dpi_x = 600, dpi_y = 600; ///< fabric resolution
};

class FabricPreview {
 public:
  /// Opens `png` (sRGB) and, if `lab` is not empty, `lab` (3 x float32 L*, a*, b*); kOutput naming
  /// the file on failure.
  [[nodiscard]] static Result<std::unique_ptr<FabricPreview>> open(const FabricColourModel& model, const PreviewSpec& spec,
                                                                   const std::filesystem::path& png,
                                                                   const std::filesystem::path& lab);
  ~FabricPreview();
  FabricPreview(const FabricPreview&) = delete;
  FabricPreview& operator=(const FabricPreview&) = delete;

  /// Adds the next fabric row (summed drop levels, inks interleaved per pixel).
  [[nodiscard]] Status add_row(std::span<const std::uint8_t> levels);
  /// Flushes the last preview row and closes both files.
  [[nodiscard]] Status close();

 private:
  struct Files;
  FabricPreview(const FabricColourModel& model, const PreviewSpec& spec);
  [[nodiscard]] Status flush();

  const FabricColourModel& model_;
  PreviewSpec spec_;
  std::uint32_t out_width_ = 0;
  std::unique_ptr<Files> files_;
  /// Per preview column: the summed XYZ of its inked fabric pixels, and how many they are. Each
  /// fabric pixel's colour comes from its own drops and the area's is the mean of those, so a
  /// colour does not depend on the preview scale (a chart read at scale 1 and a job previewed at
  /// scale 3 print alike).
  std::vector<Xyz> sums_;
  std::vector<std::uint32_t> inked_;
  /// Pixel colours by their packed drop levels (up to 8 inks): a print has few combinations.
  std::unordered_map<std::uint64_t, Xyz> cache_;
  std::uint64_t rows_in_ = 0, out_row_ = 0;
  std::vector<std::uint8_t> srgb_row_;
  std::vector<float> lab_row_;
};

}  // namespace tp::sim
