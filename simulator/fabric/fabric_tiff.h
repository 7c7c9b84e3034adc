// simulator/fabric/fabric_tiff.h: writes the virtual fabric's drop sums as a separated TIFF, row by row.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "simulator/common/error.h"

namespace tp::sim {

/// A fabric TIFF open for writing top to bottom: one 8-bit sample per ink (summed drop levels),
/// Photometric Separated with InkSet CMYK when the inks are cyan, magenta, yellow, black in that
/// order, otherwise InkSet multi-ink with one InkNames entry per ink; no alpha (no ExtraSamples),
/// X/YResolution in dots per inch, Deflate strips written as rows arrive.
class FabricTiff {
 public:
  /// Opens `path` for a width_px x height_px fabric. Fails (kOutput) naming the file; (kInvalidArgument)
  /// for zero sizes, no inks, more than 64 inks or an empty ink name.
  [[nodiscard]] static Result<std::unique_ptr<FabricTiff>> open(const std::filesystem::path& path, std::uint32_t width_px,
                                                                std::uint64_t height_px, const std::vector<std::string>& inks,
                                                                int dpi_x, int dpi_y);
  ~FabricTiff();
  FabricTiff(const FabricTiff&) = delete;
  FabricTiff& operator=(const FabricTiff&) = delete;

  /// Appends the next row: width_px * inks samples, interleaved per pixel. Fails (kOutput) naming
  /// the file and row.
  [[nodiscard]] Status write_row(const std::uint8_t* samples);
  /// Writes the directory; fails (kOutput) if rows are missing or the write fails.
  [[nodiscard]] Status close();

 private:
  struct Impl;
  explicit FabricTiff(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tp::sim
