// rip/job/screened_window.cpp: extent measurement of screened rows (word-at-a-time scans from both ends).
#include "rip/job/internal/screened_window.h"

#include <cstring>

namespace tp::rip {

namespace {
inline bool zero_word(const std::uint8_t* p) {
  std::uint64_t w;
  std::memcpy(&w, p, 8);
  return w == 0;
}
}  // namespace

void ScreenedWindow::measure_extent(std::int64_t y) {
  int first = row_bytes_, last = -1;
  for (int c = 0; c < channels_; ++c) {
    const std::uint8_t* p = row(y, c);
    // Left end: only bytes before the best start so far can improve it.
    int i = 0;
    while (i + 8 <= first && zero_word(p + i)) i += 8;
    while (i < first && p[i] == 0) ++i;
    if (i < first) first = i;
    if (i >= row_bytes_) continue;  // the whole row of this ink is blank
    // Right end: only bytes after the best end so far can improve it.
    int j = row_bytes_;
    while (j - 8 > last && j - 8 >= 0 && zero_word(p + j - 8)) j -= 8;
    while (j - 1 > last && p[j - 1] == 0) --j;
    if (j - 1 > last) last = j - 1;
  }
  set_extent(y, first, last);
}

}  // namespace tp::rip
