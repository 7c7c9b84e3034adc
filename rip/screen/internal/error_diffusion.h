// rip/screen/internal/error_diffusion.h: serpentine multi-level Floyd-Steinberg error diffusion.
#pragma once

#include <array>
#include <vector>

#include "rip/screen/screen.h"

namespace tp::rip {

/// Reference-quality screen: each pixel snaps to the nearest level and passes its error on
/// (7/16 ahead, 3/16, 5/16, 1/16 on the next row), alternating direction by row parity. Integer
/// arithmetic with exact error conservation, so output depends only on the contone rows.
class ErrorDiffusionScreen final : public Screen {
 public:
  explicit ErrorDiffusionScreen(const ScreenSetup& setup);
  void screen_row(int channel, std::int64_t row, const std::uint8_t* contone, std::uint8_t* packed) override;

 private:
  struct ChannelState {
    std::vector<std::int32_t> current, next;  ///< error carried into this row and the next (padded by 1)
    std::int64_t expected_row = 0;
  };
  ScreenSetup setup_;
  std::int32_t step_;  ///< distance between levels in 1/256 contone units
  std::array<std::uint8_t, 4> codes_{};
  std::vector<ChannelState> state_;
};

}  // namespace tp::rip
