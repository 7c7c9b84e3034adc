// rip/job/internal/separation_output.h: contone and screened separation TIFFs written as bands finish.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "rip/image/tiff_band_writer.h"
#include "rip/job/internal/band_stage.h"
#include "rip/job/internal/screened_window.h"
#include "rip/job/rip_job.h"

namespace tp::rip {

/// The separation files a job asked for, fed one band at a time.
class SeparationOutput {
 public:
  /// Opens the files. Fails (kIo/kInvalidArgument) naming the file.
  [[nodiscard]] static Result<std::unique_ptr<SeparationOutput>> open(const SeparationFiles& files,
                                                                      const std::vector<std::string>& inks,
                                                                      int width_px, std::int64_t height_px,
                                                                      int bits_per_pixel, double dpi_x, double dpi_y);
  bool wants_contone() const { return !contone_.empty(); }
  /// Writes band rows [y0, y0 + rows): contone from the band stage, codes from the window.
  /// Files are written in parallel on `pool`.
  [[nodiscard]] Status write_band(ThreadPool& pool, const BandStage& band, const ScreenedWindow& window,
                                  std::int64_t y0, int rows);
  [[nodiscard]] Status close();

 private:
  std::vector<std::unique_ptr<TiffBandWriter>> contone_, screened_;  ///< one, or one per ink
  int width_ = 0, channels_ = 0, bits_ = 2;
  std::vector<std::vector<std::uint8_t>> rows_;  ///< per file: interleaved samples of the band being written
  std::array<std::array<std::uint8_t, 8>, 256> unpack_{};  ///< packed byte -> its codes, first pixel first
};

}  // namespace tp::rip
