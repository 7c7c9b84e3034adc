// rip/screen/error_diffusion.cpp: serpentine error diffusion, one channel row at a time.
#include "rip/screen/internal/error_diffusion.h"

#include <algorithm>
#include <cstring>

namespace tp::rip {

namespace {
constexpr std::int32_t kFullScale = 255 * 256;  ///< contone 255 in 1/256 units
}

ErrorDiffusionScreen::ErrorDiffusionScreen(const ScreenSetup& setup) : setup_(setup) {
  step_ = kFullScale / (setup.levels - 1);
  for (int l = 0; l < setup.levels; ++l) codes_[l] = drop_code(setup, l);
  state_.resize(static_cast<size_t>(setup.channels));
  for (auto& s : state_) {
    s.current.assign(static_cast<size_t>(setup.width_px) + 2, 0);
    s.next.assign(static_cast<size_t>(setup.width_px) + 2, 0);
  }
}

void ErrorDiffusionScreen::screen_row(int channel, std::int64_t row, const std::uint8_t* contone,
                                      std::uint8_t* packed) {
  ChannelState& st = state_[static_cast<size_t>(channel)];
  // Row 0 (re)starts the diffusion; any other out-of-order row restarts from a clean error field.
  if (row == 0 || row != st.expected_row) {
    std::fill(st.current.begin(), st.current.end(), 0);
    std::fill(st.next.begin(), st.next.end(), 0);
  }
  st.expected_row = row + 1;
  const int width = setup_.width_px, bits = setup_.bits_per_pixel, top = setup_.levels - 1;
  std::memset(packed, 0, static_cast<size_t>(packed_row_bytes(setup_)));
  std::int32_t* cur = st.current.data() + 1;  // index -1 and width are the spill slots
  std::int32_t* nxt = st.next.data() + 1;
  const bool forward = (row & 1) == 0;
  const int dir = forward ? 1 : -1;
  for (int i = 0; i < width; ++i) {
    const int x = forward ? i : width - 1 - i;
    const std::int32_t value = contone[x] * 256 + cur[x];
    int level = (value + step_ / 2) / step_;
    if (value < 0) level = 0;
    level = std::clamp(level, 0, top);
    const std::int32_t err = value - level * step_;
    const std::int32_t e7 = err * 7 / 16, e3 = err * 3 / 16, e5 = err * 5 / 16;
    cur[x + dir] += e7;
    nxt[x - dir] += e3;
    nxt[x] += e5;
    nxt[x + dir] += err - e7 - e3 - e5;
    const std::uint8_t code = codes_[level];
    if (code) packed[(x * bits) >> 3] |= static_cast<std::uint8_t>(code << (8 - bits - ((x * bits) & 7)));
  }
  // The next row's errors become current; spill slots outside the row are dropped.
  std::swap(st.current, st.next);
  std::fill(st.next.begin(), st.next.end(), 0);
}

}  // namespace tp::rip
