// rip/job/internal/screened_window.h: the ring of screened rows a head height deep that swaths are cut from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp::rip {

/// Screened rows of every ink, addressed by absolute fabric row, kept for `slots` consecutive rows
/// (slot = row mod slots). Each row also records the extent of its non-blank bytes across inks so
/// swaths can be trimmed and blank passes skipped without rescanning the data.
class ScreenedWindow {
 public:
  ScreenedWindow(int channels, int row_bytes, int slots)
      : channels_(channels), row_bytes_(row_bytes), stride_((row_bytes + 15) / 8 * 8), slots_(slots),
        data_(static_cast<std::size_t>(slots) * channels * stride_, 0), first_(slots, 1), last_(slots, 0) {}

  int channels() const { return channels_; }
  int row_bytes() const { return row_bytes_; }
  int slots() const { return slots_; }

  std::uint8_t* row(std::int64_t y, int channel) {
    return data_.data() + (static_cast<std::size_t>(y % slots_) * channels_ + channel) * stride_;
  }
  const std::uint8_t* row(std::int64_t y, int channel) const {
    return data_.data() + (static_cast<std::size_t>(y % slots_) * channels_ + channel) * stride_;
  }
  /// Non-blank byte range [first, last] of row y over all inks; first > last when blank.
  void set_extent(std::int64_t y, int first, int last) {
    first_[static_cast<std::size_t>(y % slots_)] = first;
    last_[static_cast<std::size_t>(y % slots_)] = last;
  }
  int extent_first(std::int64_t y) const { return first_[static_cast<std::size_t>(y % slots_)]; }
  int extent_last(std::int64_t y) const { return last_[static_cast<std::size_t>(y % slots_)]; }

  /// Scans row y's inks and records their extent.
  void measure_extent(std::int64_t y);

 private:
  int channels_, row_bytes_, stride_, slots_;
  std::vector<std::uint8_t> data_;
  std::vector<int> first_, last_;
};

}  // namespace tp::rip
