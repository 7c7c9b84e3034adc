// rip/job/rip_job.h: the streaming RIP job the pipeline calls: a marker (or any band source) in,
// compressed printhead swaths out as soon as each is complete.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "device/model/printer_model.h"
#include "device/swath/swath.h"
#include "geometry/common/cancel.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/nesting/marker.h"
#include "rip/colour/ink_converter.h"
#include "rip/colour/tone_curve.h"
#include "rip/common/error.h"
#include "rip/image/image_io.h"
#include "rip/render/band_source.h"
#include "rip/screen/screen.h"
#include "rip/swath/pass_plan.h"

namespace tp::rip {

/// Separations written for other systems (checking, archiving), band by band at print resolution.
struct SeparationFiles {
  std::filesystem::path contone_tiff;   ///< 8-bit ink amounts; empty = not written
  std::filesystem::path screened_tiff;  ///< drop codes at the printer's bits per pixel; empty = not written
  /// false: one TIFF holding every ink; true: one TIFF per ink, "<stem>-<ink><ext>" beside the path.
  bool one_file_per_ink = false;
  TiffCompression compression = TiffCompression::kPackBits;
};

/// How to RIP a job. Resolution and head geometry come from the printer model.
struct RipSettings {
  int passes = 1;                       ///< 1, 2, 4, 8 (any divisor-friendly count works)
  bool bidirectional = false;           ///< alternate carriage direction per swath
  ScreenKind screen = ScreenKind::kBlueNoise;
  int drop_levels = 0;                  ///< 0: all the printer's (2^bits_per_pixel); 2: bi-level
  std::filesystem::path profile_path;   ///< printer ICC profile; empty: default CMYK (see InkConverter)
  RenderingIntent intent = RenderingIntent::kPerceptual;
  std::filesystem::path calibration_profile; ///< a calibration set's RGB profile (InkConverterSettings)
  double ink_limit_percent = 0;         ///< total ink limit, 0 = none
  std::vector<ToneCurve> linearisation; ///< empty or one per printer ink
  std::vector<std::string> device_inks;  ///< calibration charts: R, G, B drive these inks (InkConverterSettings)
  int band_rows = 128;                  ///< rows rendered per band: a multiple of kRenderTileRows
  int threads = 0;                      ///< 0: all cores
  bool skip_blank_swaths = true;        ///< passes with no ink send no swath (their feed is added to the next)
  device::SwathCompression compression = device::SwathCompression::kPackBits;
  /// Resume: swaths with a lower index are computed (identically) but not sent.
  std::uint32_t first_swath_index = 0;
  SeparationFiles separations;
  /// Print the mirror image across the roll width (sublimation transfer paper, laid face down).
  bool mirror_print = false;
};

/// Where a running job is.
struct RipProgress {
  std::int64_t band = 0;            ///< bands finished
  std::int64_t rows_done = 0;       ///< fabric rows screened
  std::int64_t rows_total = 0;
  double fabric_y_mm = 0;           ///< rows_done in mm along the roll
  std::uint32_t swaths_done = 0;    ///< swaths completed (sent or skipped for resume)
};

/// Receives each swath as soon as it is complete, on the job's calling thread; may block (flow
/// control). Returning an error stops the job with that error.
using SwathSink = std::function<Status(device::Swath&&)>;
/// Called after every band.
using ProgressCallback = std::function<void(const RipProgress&)>;

/// What a job did, with stage timings for benchmarks.
struct RipStats {
  int width_px = 0;
  std::int64_t height_px = 0;
  double area_m2 = 0;                   ///< width x length of the raster
  PassPlan plan;
  std::uint32_t swaths = 0;             ///< swaths completed (indices 0 .. swaths-1)
  std::uint32_t swaths_sent = 0;        ///< of which sent to the sink
  std::uint64_t raw_bytes = 0;          ///< uncompressed data of the sent swaths
  std::uint64_t compressed_bytes = 0;
  double compression_ratio = 1;         ///< raw / compressed
  /// Drops fired per ink and drop code (index 1 .. 3; index 0 unused), whole job.
  std::vector<std::array<std::uint64_t, 4>> drops;
  int threads = 1;
  /// Bytes of the table of every 8-bit colour, built for jobs of kDirectTableMinPixels or more with
  /// up to four inks (64 MiB, whatever the roll length; 0 when pixels interpolate the grid).
  std::uint64_t colour_table_bytes = 0;
  double wall_s = 0;
  double render_cpu_s = 0, colour_cpu_s = 0, screen_cpu_s = 0, swath_cpu_s = 0;  ///< thread CPU time, summed
  double sink_s = 0, separations_s = 0;  ///< wall time in the sink and in writing separations
};

/// RIPs `source` for `printer`: colour, screening, passes, swaths, compression, sinks and files.
/// Rows are processed in bands of settings.band_rows; memory holds one head height of screened
/// rows plus a band, whatever the roll length. Output is identical for any band_rows and threads.
/// Fails (kInvalidArgument) on bad settings or a source wider than the printer, (kColour) on the
/// profile or curves, (kSwath) on the pass plan, (kCancelled) when `cancel` fires (checked between
/// bands), (kIo) on separation files, or with the sink's own error.
[[nodiscard]] Result<RipStats> run_rip(const BandSource& source, const device::PrinterModel& printer,
                                       const RipSettings& settings, const SwathSink& sink,
                                       const ProgressCallback& progress = {},
                                       const geometry::CancelToken& cancel = {});

/// The marker mirrored across its width at `dpi_x` (x -> W - x, W the raster's width in mm): what
/// printer column c must carry when columns run against roll x.
[[nodiscard]] geometry::Marker mirrored_across_width(const geometry::Marker& marker, double dpi_x);

/// run_rip over a marker rendered through `renderer` at the printer's resolution (MarkerSource),
/// mirrored across the width when settings.mirror_print differs from a right carriage origin.
[[nodiscard]] Result<RipStats> rip_marker(const geometry::Marker& marker, const geometry::PieceRenderer& renderer,
                                          const device::PrinterModel& printer, const RipSettings& settings,
                                          const SwathSink& sink, const ProgressCallback& progress = {},
                                          const geometry::CancelToken& cancel = {});

/// Decodes a swath's data (PackBits or raw) into channel-major packed rows (raw_bytes long).
/// Fails (kSwath) naming the swath index on corrupt data or a size mismatch.
[[nodiscard]] Result<std::vector<std::uint8_t>> decode_swath_data(const device::Swath& swath);

}  // namespace tp::rip
