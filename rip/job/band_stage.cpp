// rip/job/band_stage.cpp: the per-band hot path: render tile -> inks -> drops, with per-thread scratch.
#include "rip/job/internal/band_stage.h"

#include <algorithm>
#include <cstring>

#include "rip/common/internal/cpu_clock.h"

namespace tp::rip {

namespace {
constexpr int kDropFieldBits = 21;  ///< a row of up to 2^21 bytes cannot overflow a field
}  // namespace

BandStage::BandStage(const BandSource& source, const InkConverter& ink, Screen& screen, const ScreenSetup& setup,
                     ScreenedWindow& window, int band_rows, int workers, bool keep_contone)
    : source_(source), ink_(ink), screen_(screen), setup_(setup), window_(window),
      padded_(padded_width(setup.width_px)), fused_(setup.kind == ScreenKind::kBlueNoise),
      keep_contone_(keep_contone || !fused_) {
  if (keep_contone_) band_contone_.assign(static_cast<size_t>(band_rows) * setup.channels * padded_, 0);
  scratch_.resize(static_cast<size_t>(workers));
  for (auto& s : scratch_) {
    s.rgba.resize(static_cast<size_t>(setup.width_px) * kRenderTileRows);
    s.planes.assign(static_cast<size_t>(setup.channels) * padded_, 0);  // padding stays zero
  }
  tallies_.resize(static_cast<size_t>(workers));
  for (auto& t : tallies_) t.drops.assign(static_cast<size_t>(setup.channels), {});
  // Codes packed per byte: 4 of 2 bits or 8 of 1 bit.
  const int bits = setup.bits_per_pixel, per_byte = 8 / bits, mask = (1 << bits) - 1;
  for (int b = 0; b < 256; ++b) {
    std::uint64_t f = 0;
    for (int k = 0; k < per_byte; ++k) {
      const int code = (b >> (k * bits)) & mask;
      if (code) f += std::uint64_t{1} << ((code - 1) * kDropFieldBits);
    }
    drop_table_[b] = f;
  }
}

void BandStage::count_drops(const std::uint8_t* packed, std::array<std::uint64_t, 4>& drops) const {
  const int n = packed_row_bytes(setup_);
  std::uint64_t f = 0;
  for (int i = 0; i < n; ++i) f += drop_table_[packed[i]];
  const std::uint64_t field = (std::uint64_t{1} << kDropFieldBits) - 1;
  drops[1] += f & field;
  drops[2] += (f >> kDropFieldBits) & field;
  drops[3] += (f >> (2 * kDropFieldBits)) & field;
}

void BandStage::run_tile(std::int64_t y0, int rows, std::int64_t band_y0, int worker) {
  Scratch& s = scratch_[static_cast<size_t>(worker)];
  StageTally& tally = tallies_[static_cast<size_t>(worker)];
  const int w = setup_.width_px, nc = setup_.channels;

  const double t0 = thread_cpu_seconds();
  std::memset(static_cast<void*>(s.rgba.data()), 0, sizeof(geometry::Rgba8) * static_cast<size_t>(w) * rows);
  source_.render_rows(y0, rows, s.rgba.data(), w);
  tally.render_s += thread_cpu_seconds() - t0;

  std::uint8_t* planes[16];
  for (int r = 0; r < rows; ++r) {
    const std::int64_t y = y0 + r;
    const double t1 = thread_cpu_seconds();
    // Colour: into the band buffer when it is kept, else into this thread's scratch row.
    for (int c = 0; c < nc; ++c)
      planes[c] = keep_contone_ ? band_contone_.data() + (static_cast<size_t>(y - band_y0) * nc + c) * padded_
                                : s.planes.data() + static_cast<size_t>(c) * padded_;
    const bool inked = ink_.convert_row(s.rgba.data() + static_cast<size_t>(r) * w, w, planes);
    const double t2 = thread_cpu_seconds();
    tally.colour_s += t2 - t1;
    if (!fused_) continue;
    for (int c = 0; c < nc; ++c) {
      std::uint8_t* out = window_.row(y, c);
      if (inked) {
        screen_.screen_row(c, y, planes[c], out);
        count_drops(out, tally.drops[static_cast<size_t>(c)]);
      } else {
        std::memset(out, 0, static_cast<size_t>(window_.row_bytes()));
      }
    }
    if (inked) window_.measure_extent(y);
    else window_.set_extent(y, 1, 0);
    tally.screen_s += thread_cpu_seconds() - t2;
  }
}

void BandStage::run(ThreadPool& pool, std::int64_t y0, int rows) {
  const int tiles = (rows + kRenderTileRows - 1) / kRenderTileRows;
  pool.parallel_for(tiles, [&](int t, int worker) {
    const std::int64_t ty = y0 + static_cast<std::int64_t>(t) * kRenderTileRows;
    run_tile(ty, static_cast<int>(std::min<std::int64_t>(kRenderTileRows, y0 + rows - ty)), y0, worker);
  });
  if (fused_) return;
  // Error diffusion: each ink walks the band's rows in order; inks run in parallel.
  const int nc = setup_.channels;
  pool.parallel_for(nc, [&](int c, int worker) {
    const double t0 = thread_cpu_seconds();
    StageTally& tally = tallies_[static_cast<size_t>(worker)];
    for (int r = 0; r < rows; ++r) {
      std::uint8_t* out = window_.row(y0 + r, c);
      screen_.screen_row(c, y0 + r, contone(r, c), out);
      count_drops(out, tally.drops[static_cast<size_t>(c)]);
    }
    tally.screen_s += thread_cpu_seconds() - t0;
  });
  pool.parallel_for(rows, [&](int r, int) { window_.measure_extent(y0 + r); });
}

}  // namespace tp::rip
