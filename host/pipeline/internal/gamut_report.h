// host/pipeline/internal/gamut_report.h: the report's `gamut` section: how much of the design the
// printer cannot reproduce, through the calibrated (or the default) printer profile, with the
// soft proof and its out-of-gamut overlay written beside marker.png.
#pragma once

#include "host/pipeline/internal/pipeline_state.h"

namespace tp::host::internal {

/// Soft-proofs `marker.png` (already written) through the job's calibration profile, else its
/// `print.icc_profile`, else the default CMYK press profile for a CMYK printer: writes
/// `marker-proof.png` and `marker-gamut.png` (out-of-gamut pixels in pure green) and the report's
/// `gamut` {profile, profile_source, printed_pixels, out_of_gamut_share, worst_de00, files}. Without
/// a usable profile `gamut` holds only a `reason`. Fails on an unreadable marker.png or profile.
[[nodiscard]] Status report_gamut(PipelineState& ps);

}  // namespace tp::host::internal
