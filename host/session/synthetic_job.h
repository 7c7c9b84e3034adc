// host/session/synthetic_job.h: a deterministic stream of swaths and cues that needs no RIP, for
// the link's scenario tests, `printctl bench link` and demos of the printer link alone.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "device/protocol/messages.h"
#include "device/swath/swath.h"

namespace tp::host {

struct SyntheticJob {
  std::uint32_t swaths = 24;
  std::uint32_t width_px = 1200;  ///< printed width of every swath
  std::uint32_t rows = 0;         ///< rows per swath (0: the printer's nozzles per ink)
  std::int32_t x_start_px = 64;
  bool compress = true;           ///< PackBits, as the RIP sends
  bool noise = false;             ///< screened-image-like noise instead of bands (link benchmarks)
  std::uint32_t cue_every = 4;    ///< a cut cue after every N swaths (0: none), notches between
};

/// Swath `index` of the job for `printer`: its channels, bits per pixel and dpi. Rows are
/// contiguous down the fabric (row step 1, one pass); feeds come from rounded absolute
/// positions so they never drift. Drop levels depend on the absolute fabric row and column, so
/// a swath printed twice or out of place changes the fabric.
device::Swath make_synthetic_swath(const SyntheticJob& job, const device::IdentifyMsg& printer, std::uint32_t index);

/// Fabric position (um from the job's start) of the top of swath `index`.
std::int64_t synthetic_position_um(const SyntheticJob& job, const device::IdentifyMsg& printer, std::uint32_t index);

struct SyntheticCue {
  device::CueKind kind;
  std::int64_t position_um;
  std::int32_t x_um;
};

/// The job's cues: a cut a third of a feed before the end of every `cue_every` swaths, a notch
/// mark halfway.
std::vector<SyntheticCue> synthetic_cues(const SyntheticJob& job, const device::IdentifyMsg& printer);

}  // namespace tp::host
