// simulator/fabric/fabric_canvas.h: the virtual fabric the simulated printer lays drops on, at
// printer resolution, one byte per ink per pixel (sum of drop levels). Memory holds only the
// rows the head can still reach; finished rows spill to a scratch file, so a 20 m roll costs
// disk, not memory. At the end it writes a multi-channel TIFF, and the colour the colorimetric
// printer gives (fabric_colour.h) at the preview scale as an sRGB PNG and a CIELAB TIFF.
#pragma once

#include <cstdint>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "device/swath/swath.h"
#include "simulator/common/error.h"
#include "simulator/fabric/fabric_colour.h"

namespace tp::sim {

struct FabricSpec {
  std::uint32_t width_px = 0;
  std::vector<std::string> inks;  ///< channel names, in swath channel order
  int dpi_x = 600;
  int dpi_y = 600;
  int bits_per_pixel = 2;
  /// Rows above a swath's first row that later swaths may still reach (the head's nozzle span):
  /// only rows further up leave memory.
  std::int64_t reach_rows = 0;
  /// Printer columns run against roll x (carriage origin over the right selvedge): the files show
  /// column c at width_px - 1 - c, so they always show the printed face in the roll frame.
  bool columns_reversed = false;
  /// How the inks look on the fabric; its `inks` are taken from `inks` above.
  FabricLook look;
  /// File name, beside the PNG, of the CIELAB preview (float L*, a*, b*); empty = none.
  std::string lab_file_name = "fabric-lab.tif";
};

struct FabricSummary {
  std::uint32_t width_px = 0;
  std::uint64_t height_px = 0;
  int preview_scale = 1;               ///< fabric pixels per preview pixel, each way
  std::uint64_t clipped_pixels = 0;    ///< drops outside the fabric width (lost)
  std::uint64_t late_rows = 0;         ///< swath rows behind the head (should be 0)
  std::uint64_t peak_window_rows = 0;  ///< most rows held in memory at once
};

class FabricCanvas {
 public:
  /// `scratch` is a file for finished rows (created, removed when the canvas goes).
  [[nodiscard]] static Result<std::unique_ptr<FabricCanvas>> create(FabricSpec spec,
                                                                    const std::filesystem::path& scratch);
  ~FabricCanvas();
  FabricCanvas(const FabricCanvas&) = delete;
  FabricCanvas& operator=(const FabricCanvas&) = delete;

  /// Adds the drops of a swath whose row 0 landed on `fabric_row`. Rows more than reach_rows
  /// above `fabric_row` are finished (the fabric only moves forward) and leave memory.
  void lay(const device::SwathHeader& header, std::span<const std::uint8_t> raw, std::int64_t fabric_row);
  /// Writes `tif` (all inks, levels summed per pixel), `png` (sRGB) and the CIELAB file beside it
  /// (both downscaled by an integer factor so they are at most `preview_max_width` wide). Fails
  /// with kOutput naming the file.
  [[nodiscard]] Result<FabricSummary> finish(const std::filesystem::path& tif, const std::filesystem::path& png,
                                             std::uint32_t preview_max_width = 4096);

 private:
  FabricCanvas(FabricSpec spec, FabricColourModel colour, std::FILE* scratch, std::filesystem::path scratch_path);
  void spill_until(std::int64_t row);
  std::vector<std::uint8_t>& row(std::int64_t r);

  FabricSpec spec_;
  FabricColourModel colour_;
  std::size_t row_bytes_;
  std::FILE* scratch_;
  std::filesystem::path scratch_path_;
  std::deque<std::vector<std::uint8_t>> window_;
  std::int64_t base_row_ = 0;  ///< fabric row of window_.front()
  std::uint64_t spilled_rows_ = 0;
  FabricSummary summary_;
};

}  // namespace tp::sim
