// host/session/synthetic_job.cpp: deterministic synthetic swaths and cues.
#include "host/session/synthetic_job.h"

#include <cmath>

#include "device/swath/packbits.h"

namespace tp::host {

namespace {

std::uint32_t rows_of(const SyntheticJob& job, const device::IdentifyMsg& p) {
  return job.rows ? job.rows : std::max<std::uint32_t>(1, p.nozzles_per_ink);
}

// A small integer hash: noise that is the same wherever and however often it is computed.
std::uint32_t mix(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

}  // namespace

std::int64_t synthetic_position_um(const SyntheticJob& job, const device::IdentifyMsg& p, std::uint32_t index) {
  const double row = static_cast<double>(index) * rows_of(job, p);
  return std::llround(row * 25400.0 / p.dpi_y);
}

device::Swath make_synthetic_swath(const SyntheticJob& job, const device::IdentifyMsg& p, std::uint32_t index) {
  device::Swath s;
  device::SwathHeader& h = s.header;
  h.index = index;
  h.rows = rows_of(job, p);
  h.first_row = static_cast<std::int64_t>(index) * h.rows;
  h.row_step = 1;
  h.x_start_px = job.x_start_px;
  h.width_px = job.width_px;
  h.channels = static_cast<std::uint8_t>(p.inks.size());
  h.bits_per_pixel = p.bits_per_pixel;
  h.direction = index % 2 ? device::CarriageDirection::kRightToLeft : device::CarriageDirection::kLeftToRight;
  h.feed_before_um = index == 0 ? 0
                                : static_cast<std::uint32_t>(synthetic_position_um(job, p, index) -
                                                             synthetic_position_um(job, p, index - 1));
  const std::uint32_t rb = device::swath_row_bytes(h);
  h.raw_bytes = static_cast<std::uint32_t>(device::swath_raw_bytes(h));
  std::vector<std::uint8_t> raw(h.raw_bytes, 0);
  const int bpp = h.bits_per_pixel;
  const unsigned max_level = (1u << bpp) - 1;
  for (std::uint32_t c = 0; c < h.channels; ++c)
    for (std::uint32_t r = 0; r < h.rows; ++r) {
      const std::int64_t y = h.first_row + r;
      std::uint8_t* row = raw.data() + (static_cast<std::size_t>(c) * h.rows + r) * rb;
      for (std::uint32_t x = 0; x < h.width_px; ++x) {
        const std::int64_t fx = h.x_start_px + x;
        unsigned level;
        if (job.noise) {
          level = mix(static_cast<std::uint32_t>(y * 131071 + fx * 8191 + c * 127)) % (max_level + 1);
        } else {
          // Diagonal bands per ink, offset by channel, with a clear gap every 64 rows.
          const std::int64_t band = ((fx + y + c * 37) / 48) % 4;
          level = (y % 64 < 4) ? 0 : static_cast<unsigned>(band) % (max_level + 1);
        }
        const std::size_t bit = static_cast<std::size_t>(x) * bpp;
        row[bit / 8] |= static_cast<std::uint8_t>(level << (8 - bpp - bit % 8));
      }
    }
  if (job.compress) {
    h.compression = device::SwathCompression::kPackBits;
    device::packbits_encode(raw, s.data);
  } else {
    h.compression = device::SwathCompression::kNone;
    s.data = std::move(raw);
  }
  return s;
}

std::vector<SyntheticCue> synthetic_cues(const SyntheticJob& job, const device::IdentifyMsg& p) {
  std::vector<SyntheticCue> cues;
  if (job.cue_every == 0) return cues;
  const std::int32_t x_um = static_cast<std::int32_t>(std::lround(job.x_start_px * 25400.0 / p.dpi_x));
  for (std::uint32_t k = job.cue_every; k <= job.swaths; k += job.cue_every) {
    const std::uint32_t half = k - job.cue_every / 2;
    if (job.cue_every >= 2) cues.push_back({device::CueKind::kNotch, synthetic_position_um(job, p, half), x_um});
    // Cuts sit a third of a feed before a swath boundary: the printer reaches them with the
    // next feed, so where they fire shows the one-feed-step tolerance honestly.
    const std::int64_t end = synthetic_position_um(job, p, k);
    cues.push_back({device::CueKind::kCut, end - (end - synthetic_position_um(job, p, k - 1)) / 3, 0});
  }
  return cues;
}

}  // namespace tp::host
