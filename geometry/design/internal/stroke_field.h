// geometry/design/internal/stroke_field.h: a brush stroke on the garment surface: the stroke
// snapped onto the surface, and for each part of it the region of the garment it can reach
// along the surface, so distances never cut through the body.
#pragma once

#include <array>
#include <vector>

#include "geometry/design/design.h"
#include "geometry/design/internal/closest_point.h"
#include "geometry/design/internal/garment_surface.h"

namespace tp::geometry::internal {

/// A stroke segment between two snapped surface points.
struct StrokeSegment {
  Vec3 a, b;
};

class StrokeField {
 public:
  /// Resamples the stroke every `spacing` (at most a quarter radius), snaps each sample to the
  /// garment, and floods the surface from each chunk of the stroke (Dijkstra on the mesh edges,
  /// limited to a little more than the radius).
  StrokeField(const BrushStroke& stroke, const GarmentSurface& surface, const ClosestPointIndex& garment_index);

  const std::vector<StrokeSegment>& segments() const { return segments_; }
  double radius_mm() const { return radius_mm_; }
  double hardness() const { return hardness_; }

  /// Segments that may lie within the radius of a triangle whose corners are at the given chart
  /// locations (piece, location) and 3D points; appended to `out` as segment indices.
  void candidates(const std::array<int, 3>& piece, const std::array<ChartLocation, 3>& loc,
                  const std::array<Vec3, 3>& corner_mm, std::vector<int>& out) const;

  /// Brush coverage 0..1 at surface distance `d_mm` from the stroke for a pixel `pixel_mm` wide.
  double coverage(double d_mm, double pixel_mm) const;

 private:
  double reach(int chunk, int piece, const ChartLocation& loc) const;
  const GarmentSurface& surface_;
  std::vector<StrokeSegment> segments_;
  std::vector<std::array<int, 2>> chunks_;          // segment ranges [first, last)
  std::vector<std::vector<float>> chunk_distance_;  // per chunk, per 3D vertex; +inf unreached
  double radius_mm_ = 5, hardness_ = 0.8, gate_slack_mm_ = 0;
};

/// Distance from p to segment ab in mm.
double point_segment_distance(Vec3 p, Vec3 a, Vec3 b);

/// Smallest distance between segments pq and ab in mm.
double segment_segment_distance(Vec3 p, Vec3 q, Vec3 a, Vec3 b);

}  // namespace tp::geometry::internal
