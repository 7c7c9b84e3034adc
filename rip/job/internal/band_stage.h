// rip/job/internal/band_stage.h: one band of the roll through rendering, colour and screening, spread
// over the job's threads.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/common/thread_pool.h"
#include "rip/colour/ink_converter.h"
#include "rip/job/internal/screened_window.h"
#include "rip/render/band_source.h"
#include "rip/screen/screen.h"

namespace tp::rip {

/// Per-thread CPU time and drop tallies (merged into RipStats at the end).
struct StageTally {
  double render_s = 0, colour_s = 0, screen_s = 0;
  std::vector<std::array<std::uint64_t, 4>> drops;
};

/// Renders, converts and screens bands into the window. Threshold screens run fused per render
/// tile (the tile's rows stay in cache); error diffusion screens each ink's rows in order after
/// the band's colour conversion. When `keep_contone`, the band's contone rows stay available for
/// separation files.
class BandStage {
 public:
  BandStage(const BandSource& source, const InkConverter& ink, Screen& screen, const ScreenSetup& setup,
            ScreenedWindow& window, int band_rows, int workers, bool keep_contone);

  /// Processes rows [y0, y0 + rows) (y0 a multiple of kRenderTileRows).
  void run(ThreadPool& pool, std::int64_t y0, int rows);

  /// Contone of band row r (0-based in the last band), ink c: padded_width bytes.
  const std::uint8_t* contone(int r, int c) const {
    return band_contone_.data() + (static_cast<size_t>(r) * setup_.channels + c) * padded_;
  }
  const std::vector<StageTally>& tallies() const { return tallies_; }

 private:
  struct Scratch {
    std::vector<geometry::Rgba8> rgba;       ///< one render tile
    std::vector<std::uint8_t> planes;        ///< channels x padded width contone for one row
  };
  void run_tile(std::int64_t y0, int rows, std::int64_t band_y0, int worker);
  void count_drops(const std::uint8_t* packed, std::array<std::uint64_t, 4>& drops) const;

  const BandSource& source_;
  const InkConverter& ink_;
  Screen& screen_;
  ScreenSetup setup_;
  ScreenedWindow& window_;
  int padded_;
  bool fused_, keep_contone_;
  std::vector<std::uint8_t> band_contone_;
  std::vector<Scratch> scratch_;
  std::vector<StageTally> tallies_;
  std::array<std::uint64_t, 256> drop_table_{};  ///< per packed byte: counts of codes 1..3 in 21-bit fields
};

}  // namespace tp::rip
