// rip/screen/internal/threshold_screen.h: the blue-noise threshold-array screen.
#pragma once

#include <array>
#include <vector>

#include "rip/screen/screen.h"

namespace tp::rip {

/// Multi-level ordered dither against a blue-noise tile: level = (v * M + d) >> 16 with
/// M = (levels - 1) * 65535 / 255 and d in (0, 65536) the tile's threshold, so a tone between two
/// levels fires the upper one on a blue-noise fraction of pixels. Each channel reads the tile
/// under its own mirror/rotation and offset so inks do not stack their dots.
class ThresholdScreen final : public Screen {
 public:
  explicit ThresholdScreen(const ScreenSetup& setup);
  void screen_row(int channel, std::int64_t row, const std::uint8_t* contone, std::uint8_t* packed) override;

 private:
  ScreenSetup setup_;
  std::uint32_t multiplier_;
  std::array<std::uint8_t, 4> codes_{};
  std::vector<std::vector<std::uint16_t>> tiles_;  ///< per channel, kBlueNoiseSize^2 thresholds
};

}  // namespace tp::rip
