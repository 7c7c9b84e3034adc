// rip/screen/screen.h: screening (halftoning): contone ink amounts to packed drop sizes, row by row.
#pragma once

#include <cstdint>
#include <memory>

#include "rip/common/error.h"

namespace tp::rip {

/// Which halftone.
enum class ScreenKind {
  kBlueNoise,       ///< threshold array: fast, parallel, deterministic by fabric coordinates
  kErrorDiffusion,  ///< serpentine Floyd-Steinberg: reference quality, rows strictly in order
};

/// What a screen produces.
struct ScreenSetup {
  ScreenKind kind = ScreenKind::kBlueNoise;
  int channels = 4;
  int levels = 4;          ///< tone levels incl. "no drop": 2 = bi-level, 4 = none/small/medium/large
  int bits_per_pixel = 2;  ///< packed code width: 1 or 2 (levels <= 2^bits)
  int width_px = 0;        ///< row width; rows start at fabric column 0
};

/// Bytes of one packed row.
inline int packed_row_bytes(const ScreenSetup& s) { return (s.width_px * s.bits_per_pixel + 7) / 8; }

/// Contone row width the screens read: width_px rounded up to whole 128-pixel blocks. The caller
/// keeps the padding zero so the inner loops run on fixed-size blocks.
inline int padded_width(int width_px) { return (width_px + 127) / 128 * 128; }

/// Drop code written for tone level `level`: level itself when levels == 2^bits; otherwise spread
/// so the top level is the largest drop (bi-level on a 2-bit head fires large drops).
inline std::uint8_t drop_code(const ScreenSetup& s, int level) {
  const int max_code = (1 << s.bits_per_pixel) - 1;
  return static_cast<std::uint8_t>((level * max_code + (s.levels - 1) / 2) / (s.levels - 1));
}

/// A screen. Rows are fabric rows (absolute, from 0 at the start of the marker).
class Screen {
 public:
  virtual ~Screen() = default;

  /// Screens row `row` of ink `channel`: `contone` holds padded_width(width_px) amounts (0 = no ink,
  /// 255 = full), `packed` receives packed_row_bytes codes, MSB first. Threshold screens may be
  /// called for any rows from any threads (distinct rows or channels at once); error diffusion
  /// needs rows 0, 1, 2, ... of each channel in order (channels may run in parallel).
  virtual void screen_row(int channel, std::int64_t row, const std::uint8_t* contone, std::uint8_t* packed) = 0;
};

/// Makes the screen `setup` asks for. Fails (kScreen) on unsupported levels/bits/channels/width.
[[nodiscard]] Result<std::unique_ptr<Screen>> make_screen(const ScreenSetup& setup);

}  // namespace tp::rip
