// geometry/continuity/continuity.h: print continuity, measured: across every stitched seam and
// between every seam allowance and the strip it copies, as CIEDE2000 differences of the rendered
// contone raster (the same PieceRenderer the RIP uses, before screening).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/allowance/finishing.h"
#include "geometry/common/error.h"
#include "geometry/continuity/ciede2000.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Summary of a set of colour differences.
struct DeltaEStats {
  std::size_t samples = 0;
  double mean = 0;
  double p95 = 0;
  double max = 0;
};

/// One stitched seam: the two edges sewn together.
struct SeamContinuity {
  std::string piece_a, edge_a, piece_b, edge_b;
  DeltaEStats de00;
};

/// One edge's allowance against the strip it copies.
struct AllowanceContinuity {
  std::string piece, edge;
  std::string source_piece;  ///< partner (category 1) or the piece itself (category 2)
  int category = 2;
  DeltaEStats de00;
};

/// A sample pair, for finding where a difference comes from.
struct SamplePair {
  double de00 = 0;
  std::string piece_a, piece_b;
  Vec2 at_a_mm, at_b_mm;
  Rgba8 colour_a, colour_b;
};

/// The job report's `seams` and `allowance` figures.
struct ContinuityReport {
  double dpi = 0;
  DeltaEStats seams;       ///< over all seam samples
  DeltaEStats allowance;   ///< over all allowance samples
  std::vector<SeamContinuity> seam_list;
  std::vector<AllowanceContinuity> allowance_list;
  std::vector<SamplePair> worst_seam_samples;       ///< the largest few, largest first
  std::vector<SamplePair> worst_allowance_samples;
};

struct ContinuityOptions {
  /// Between samples along a seam; 0: one pixel at the dpi, at least 0.2 mm (allowance samples,
  /// at each depth, at least 0.4 mm).
  double spacing_mm = 0;
  std::vector<double> depth_fractions{0.25, 0.5, 0.75};  ///< allowance sample depths, of its width
  /// Where the colours come from. Empty: the renderer's contone pixel at the dpi, over white.
  /// Set: the colour at a piece-local point (mm) as something else shows it, for example the
  /// printed fabric read where the marker placed the piece; nullopt skips the sample pair.
  std::function<std::optional<Lab>(int piece, Vec2 at_mm)> sample;
  /// Threads comparing sample pairs (0: every core); `sample` is then called from all of them.
  /// The figures are the same for any count.
  int threads = 0;
};

/// Samples every stitched seam at pairs of pixels centred on the same 3D point in both pieces,
/// and every allowance at a few depths against the source pixel its print was copied from,
/// rendering each at `dpi` through `renderer`, composited over white; CIEDE2000 per pair.
/// Samples where the allowance is cut away (outside the cut outline, folded-over concave parts),
/// where the source point had to be clamped into a narrow partner, whose pixel straddles a
/// line where the source changes (mitres at corners), or on a printed label are skipped.
/// With `options.sample` the same pairs are read through it instead (the printed-seam figures).
/// Fails when the garment does not match the pattern or dpi is not positive.
[[nodiscard]] Result<ContinuityReport> measure_continuity(const Pattern& pattern, const Garment& garment,
                                                         const Finishing& finishing, const PieceRenderer& renderer,
                                                         double dpi, const ContinuityOptions& options = {});

/// The report as JSON: {"dpi":..,"seams":{"samples","de00_mean","de00_p95","de00_max","list":[..]},
/// "allowance":{...}}.
std::string continuity_json(const ContinuityReport& report);

/// Mean, 95th percentile (nearest rank) and maximum of `values` (reordered).
DeltaEStats summarise(std::vector<double>& values);

}  // namespace tp::geometry
