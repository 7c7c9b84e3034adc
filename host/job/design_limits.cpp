// host/job/design_limits.cpp: counting a job's design cost against the package limits.
#include "host/job/design_limits.h"

#include <algorithm>

#include "host/job/internal/image_header.h"

namespace tp::host {

namespace {

constexpr std::uint64_t kBytesPerSourcePixel = 4;   // RGBA8, as rip::read_image holds it
constexpr std::uint64_t kBytesPerStrokePoint = 256; // point, segment and its spatial index

std::string over(const std::string& what, std::uint64_t value, std::uint64_t limit, const char* name) {
  return what + ": " + std::to_string(value) + ", over the limit of " + std::to_string(limit) + " (" + name +
         "; raise it with --limit " + name + "=N)";
}

std::uint64_t layer_pixels(const DesignLayerSpec& l) {
  if (!l.procedural.empty()) {
    const auto s = static_cast<std::uint64_t>(std::max(l.procedural_size_px, 0));
    return s * s;
  }
  if (l.image) {
    if (auto d = internal::read_image_dimensions(*l.image))
      return static_cast<std::uint64_t>(std::max<std::int64_t>(d->width_px, 0)) *
             static_cast<std::uint64_t>(std::max<std::int64_t>(d->height_px, 0));
  }
  return 0;
}

}  // namespace

DesignCost measure_design(const Job& job) {
  DesignCost c;
  c.layers = job.design.size();
  std::uint64_t points = 0;
  for (const auto& l : job.design) {
    c.max_stroke_points = std::max<std::uint64_t>(c.max_stroke_points, l.points_mm.size());
    points += l.points_mm.size();
    c.source_pixels += layer_pixels(l);
  }
  c.estimated_bytes = c.source_pixels * kBytesPerSourcePixel + points * kBytesPerStrokePoint;
  return c;
}

Status check_design_limits(const Job& job, const PackageLimits& limits) {
  std::vector<std::string> problems;
  if (job.design.size() > limits.max_design_layers)
    problems.push_back(over("job.json: /design/layers: layers", job.design.size(), limits.max_design_layers, "max_layers"));
  for (size_t i = 0; i < job.design.size(); ++i) {
    const auto n = job.design[i].points_mm.size();
    if (n > limits.max_stroke_points)
      problems.push_back(over("job.json: /design/layers/" + std::to_string(i) + "/points: points", n,
                              limits.max_stroke_points, "max_stroke_points"));
  }
  const DesignCost c = measure_design(job);
  if (c.source_pixels > limits.max_source_pixels)
    problems.push_back(over("job.json: /design/layers: source pixels of all layers", c.source_pixels,
                            limits.max_source_pixels, "max_source_pixels"));
  if (c.estimated_bytes > limits.max_memory_bytes)
    problems.push_back(over("job.json: /design: estimated memory in bytes", c.estimated_bytes, limits.max_memory_bytes,
                            "max_memory_bytes"));
  if (problems.empty()) return {};
  std::string msg;
  for (const auto& p : problems) msg += (msg.empty() ? "" : "\n") + p;
  return fail(ErrorCode::kValidation, msg);
}

}  // namespace tp::host
