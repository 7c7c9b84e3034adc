// rip/screen/screen.cpp: validates a screen setup and builds the screen it names.
#include "rip/screen/screen.h"

#include <spdlog/fmt/fmt.h>

#include "rip/screen/internal/error_diffusion.h"
#include "rip/screen/internal/threshold_screen.h"

namespace tp::rip {

Result<std::unique_ptr<Screen>> make_screen(const ScreenSetup& s) {
  if (s.bits_per_pixel != 1 && s.bits_per_pixel != 2)
    return fail(ErrorCode::kScreen, fmt::format("screen: bits_per_pixel {} is not 1 or 2", s.bits_per_pixel));
  if (s.levels < 2 || s.levels > (1 << s.bits_per_pixel))
    return fail(ErrorCode::kScreen, fmt::format("screen: {} levels do not fit {} bits per pixel", s.levels,
                                                s.bits_per_pixel));
  if (s.channels < 1 || s.channels > 16)
    return fail(ErrorCode::kScreen, fmt::format("screen: {} ink channels (1..16 supported)", s.channels));
  if (s.width_px < 1)
    return fail(ErrorCode::kScreen, fmt::format("screen: row width {} px", s.width_px));
  switch (s.kind) {
    case ScreenKind::kBlueNoise: return std::make_unique<ThresholdScreen>(s);
    case ScreenKind::kErrorDiffusion: return std::make_unique<ErrorDiffusionScreen>(s);
  }
  return fail(ErrorCode::kScreen, "screen: unknown kind");
}

}  // namespace tp::rip
