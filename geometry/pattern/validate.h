// geometry/pattern/validate.h: checks a pattern is sound before meshing, sewing or cutting it.
#pragma once

#include <vector>

#include "geometry/common/error.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// Tolerances of the checks; each has its own purpose.
struct ValidationOptions {
  /// Largest gap in mm between an edge's end and the next edge's start that still closes.
  double join_tolerance_mm = 0.01;
  /// Edges shorter than this (mm) are zero-length.
  double min_edge_length_mm = 0.01;
  /// Stitched spans may differ in length by the larger of this (mm) and the ratio below times
  /// the longer span. Eased seams (sleeve caps) need a larger ratio from the job.
  double stitch_length_tolerance_mm = 1.0;
  double stitch_length_tolerance_ratio = 0.005;
  /// Span ends may overshoot their edge by this much (mm) before they are out of range.
  double span_range_tolerance_mm = 0.05;
  /// Report clockwise outlines (true) or accept them (false, e.g. before orient_counter_clockwise).
  bool require_counter_clockwise = true;
};

/// The ease ratio (longer side over shorter) a stitch whose sides differ by more than the
/// stitched-length tolerance must be marked with to be valid; 0 when its sides agree within it
/// (or a side is empty). Importers and the stitch suggester mark their mismatched stitches so.
double mismatch_ease_ratio(const Pattern& pattern, const Stitch& stitch, const ValidationOptions& options = {});

/// Every problem found, each an Error naming the piece, edge, notch or stitch; empty when sound.
/// Checks: piece and edge names present and unique; at least 3 outline vertices; every edge has
/// >= 2 finite points and a length >= min_edge_length_mm; consecutive edges join (closed outline);
/// no self-intersection; counter-clockwise (positive area); notches, darts, fold edge and grain
/// refer to existing edges and positions; stitches refer to existing pieces and edges, spans lie
/// on their edge, and stitched lengths agree within the tolerance (both lengths in the message).
std::vector<Error> find_pattern_problems(const Pattern& pattern, const ValidationOptions& options = {});

/// The first problem of find_pattern_problems (with "and N more problems" appended), or success.
[[nodiscard]] Status validate_pattern(const Pattern& pattern, const ValidationOptions& options = {});

}  // namespace tp::geometry
