// host/pipeline/internal/printed_seams.h: seams and allowances measured on what was printed (the
// printed fabric's CIELAB image, read where the marker placed each piece), and the test hook that
// prints a piece off its planned place so the measure can be shown to see it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "geometry/continuity/continuity.h"
#include "geometry/nesting/marker.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/printed_fabric_wait.h"

namespace tp::host::internal {

/// Side of the square aperture the printed fabric is averaged over at each sample point (in XYZ):
/// the descreening low-pass at the printer's resolution, kPrintedApertureDrops drop pitches and
/// never less than kPrintedApertureMin_mm (2 mm at 150 dpi, 1 mm at 300 dpi and finer).
inline constexpr double kPrintedApertureDrops = 12;
inline constexpr double kPrintedApertureMin_mm = 1.0;
[[nodiscard]] double printed_aperture_mm(int printer_dpi);
/// Sample points closer than this many apertures to a corner of their piece's seam line (an edge's
/// end), or closer than 0.75 aperture to its cut line, are not read on the fabric.
inline constexpr double kPrintedCornerClearance = 2.0;

/// What the printed-seam measure found: the figures, or why there are none.
struct PrintedSeams {
  std::optional<geometry::ContinuityReport> report;
  std::filesystem::path fabric_lab;  ///< the image read
  std::string reason;                ///< set when there is no report
};

/// After the print: finds this job's printed fabric (printsim writes `fabric-lab.tif` and then
/// `printer.json` once the job has ended; waits for them up to `wait_s`, wait_for_printed_fabric),
/// and measures the same seam and allowance sample pairs as the contone figures at `dpi` on it,
/// each point taken from piece mm to the roll by the marker's placement of the piece (the first,
/// when several). Fails on
/// a fabric image that exists but cannot be read or used, and (kPrinter) when printsim printed the
/// job but recorded nothing for it within `wait_s`.
[[nodiscard]] Result<PrintedSeams> measure_printed_seams(const PipelineState& ps, double dpi,
                                                         double wait_s = kPrintedFabricTimeout_s);

/// Same, on a given fabric image (CIELAB float, roll frame, with its resolution).
[[nodiscard]] Result<PrintedSeams> measure_printed_seams_on(const PipelineState& ps, double dpi,
                                                            const std::filesystem::path& fabric_lab);

/// The marker as it will be printed: `ps.roll`, or with RunOptions::misplace_for_test applied (that
/// piece's placements moved by the offset and turned about the centre of its cut outline).
[[nodiscard]] Result<geometry::Marker> printed_roll(const PipelineState& ps);

}  // namespace tp::host::internal
