// geometry/pattern/outline_segments.cpp: corner detection and edge assembly for drawn outlines.
#include "geometry/pattern/outline_segments.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/pattern/curve.h"

namespace tp::geometry {
namespace {

/// Length (mm) over which an end direction is measured: long enough to average out flattening,
/// short enough to stay near the end of small curves.
constexpr double kDirectionBaseline_mm = 0.5;
/// Segments shorter than this (mm) are dropped as drawing noise.
constexpr double kMinSegmentLength_mm = 1e-6;

}  // namespace

Vec2 edge_end_direction(const Edge& edge, bool at_end) {
  double len = edge_length_mm(edge);
  if (!(len > 0)) return {};
  double d = std::min(kDirectionBaseline_mm, len / 2);
  if (at_end) return normalized(edge.points_mm.back() - point_along_edge(edge, len - d));
  return normalized(point_along_edge(edge, d) - edge.points_mm.front());
}

std::vector<Edge> edges_from_segments(std::vector<OutlineSegment> segments, double corner_angle_deg, bool detect_angles) {
  segments.erase(std::remove_if(segments.begin(), segments.end(),
                                [](const OutlineSegment& s) { return !(edge_length_mm(s.edge) > kMinSegmentLength_mm); }),
                 segments.end());
  const size_t n = segments.size();
  std::vector<Edge> out;
  if (n == 0) return out;
  const double cos_limit = std::cos(corner_angle_deg * std::numbers::pi / 180);
  std::vector<bool> corner(n, false);
  for (size_t i = 0; i < n; ++i) {
    const OutlineSegment& prev = segments[(i + n - 1) % n];
    corner[i] = segments[i].corner_before;
    if (detect_angles && !corner[i]) {
      Vec2 din = edge_end_direction(prev.edge, true), dout = edge_end_direction(segments[i].edge, false);
      corner[i] = dot(din, dout) < cos_limit;
    }
  }
  size_t first = 0;
  while (first < n && !corner[first]) ++first;
  if (first == n) first = 0;
  // Walk once round from the first corner, starting a new edge at every corner.
  for (size_t k = 0; k < n; ++k) {
    size_t i = (first + k) % n;
    if (k == 0 || corner[i]) {
      out.push_back(segments[i].edge);
    } else {
      out.back() = joined_edges(out.back(), segments[i].edge);
    }
  }
  for (size_t i = 0; i < out.size(); ++i) out[i].name = "e" + std::to_string(i);
  return out;
}

}  // namespace tp::geometry
