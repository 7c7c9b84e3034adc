// geometry/nesting/nest_pieces.cpp: pieces to strip items (grain, mirror, pairs) through the
// strip frame (internal/strip_frame.h), and the split into markers of bounded length.
#include "geometry/nesting/nest_pieces.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include "geometry/nesting/internal/strip_frame.h"
#include "geometry/nesting/strip_nester.h"

namespace tp::geometry {
namespace {

// Expected utilisation when estimating how many markers a job needs (only splits the time).
constexpr double kPlanningUtilisation = 0.8;

using nesting::normalise_deg;

// Piece y up to roll y down (PiecePlacement::piece_to_roll starts with it).
Vec2 face_up(Vec2 v) { return {v.x, -v.y}; }

Status check(const std::vector<NestItem>& items, const NestOptions& o) {
  auto bad = [](const std::string& m) { return fail(ErrorCode::kInvalidArgument, "nesting: " + m); };
  if (!(o.fabric_width_mm > 0) || !std::isfinite(o.fabric_width_mm)) return bad("fabric width must be > 0 mm");
  if (!(o.max_length_mm >= 0) || !std::isfinite(o.max_length_mm)) return bad("maximum marker length must be >= 0 mm");
  if (!(o.end_margin_mm >= 0)) return bad("end margin must be >= 0 mm");
  if (o.max_length_mm > 0 && 2 * o.end_margin_mm >= o.max_length_mm) return bad("end margins leave no marker length");
  if (items.empty()) return bad("no pieces to nest");
  for (const NestItem& it : items) {
    const std::string name = "piece '" + it.name + "'";
    if (it.quantity < 0) return bad(name + ": quantity must be >= 0");
    if (!(norm(it.grain) > 0) || !std::isfinite(it.grain.x) || !std::isfinite(it.grain.y))
      return fail(ErrorCode::kInvalidPattern, "nesting: " + name + ": grain direction is zero or not a number");
  }
  return {};
}

// One strip item per piece, two for left/right pairs (as drawn, and mirrored).
struct ItemOrigin {
  size_t nest_item = 0;
};

void add_strip_items(const NestItem& it, size_t index, std::vector<StripItem>& out, std::vector<ItemOrigin>& origin) {
  Polygon shape;
  shape.reserve(it.outline_mm.size());
  for (Vec2 v : it.outline_mm) shape.push_back(nesting::piece_to_strip_item(v));
  auto make = [&](std::vector<bool> mirrors, int demand) {
    StripItem s;
    s.id = static_cast<int>(out.size());
    s.name = "piece '" + it.name + "'";
    s.shape = shape;
    s.demand = demand;
    s.poses.clear();
    s.free_rotation = it.rotation == PieceRotation::kFree;
    for (bool m : mirrors)
      for (double deg : grain_rotations_deg(it.grain, it.rotation, m))
        s.poses.push_back({nesting::roll_to_strip_deg(deg, m), m});
    out.push_back(std::move(s));
    origin.push_back({index});
  };
  switch (it.mirror) {
    case PieceMirror::kNever: make({false}, it.quantity); break;
    case PieceMirror::kAllowed: make({false, true}, it.quantity); break;
    case PieceMirror::kPairs:
      make({false}, it.quantity);
      make({true}, it.quantity);
      break;
  }
}

}  // namespace

std::vector<double> grain_rotations_deg(Vec2 grain, PieceRotation rule, bool mirrored) {
  const Vec2 f = face_up(grain);
  const Vec2 g = mirrored ? Vec2{-f.x, f.y} : f;
  const double base = normalise_deg(90.0 - std::atan2(g.y, g.x) * 180.0 / std::numbers::pi);
  switch (rule) {
    case PieceRotation::kOneWay: return {base};
    case PieceRotation::kGrainBothWays: return {base, normalise_deg(base + 180)};
    case PieceRotation::kQuarterTurns:
      return {base, normalise_deg(base + 90), normalise_deg(base + 180), normalise_deg(base + 270)};
    case PieceRotation::kFree: return {base};
  }
  return {base};
}

Result<std::vector<Marker>> nest_pieces(const std::vector<NestItem>& items, const NestOptions& options,
                                        const CancelToken& cancel, NestStats* stats) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  if (auto ok = check(items, options); !ok) return std::unexpected(ok.error());

  std::vector<StripItem> strip_items;
  std::vector<ItemOrigin> origin;
  for (size_t i = 0; i < items.size(); ++i) add_strip_items(items[i], i, strip_items, origin);
  std::vector<int> remaining(strip_items.size());
  for (size_t i = 0; i < strip_items.size(); ++i) remaining[i] = strip_items[i].demand;

  std::vector<Marker> markers;
  double roll_y = 0;
  std::uint64_t work_used = 0;  // separator iterations spent on earlier markers
  const double tail = options.end_margin_mm;
  for (;;) {
    StripProblem problem;
    problem.name = "marker " + std::to_string(markers.size() + 1);
    problem.width = options.fabric_width_mm;
    std::vector<int> problem_item;  // problem item -> strip item
    double area_left = 0;
    for (size_t i = 0; i < strip_items.size(); ++i) {
      if (remaining[i] == 0) continue;
      StripItem s = strip_items[i];
      s.demand = remaining[i];
      area_left += std::fabs(signed_area(s.shape)) * s.demand;
      problem.items.push_back(std::move(s));
      problem_item.push_back(static_cast<int>(i));
    }
    if (problem.items.empty()) break;
    // Defects in this marker's frame: roll y measured from the marker start becomes strip x.
    for (const Polygon& d : options.defects_mm) {
      Polygon local;
      for (Vec2 v : d) local.push_back(nesting::roll_to_strip(Vec2{v.x, v.y - roll_y}));
      const Box2 b = bounds(local);
      if (b.max.x < 0 || (options.max_length_mm > 0 && b.min.x > options.max_length_mm)) continue;
      problem.hazards.push_back(std::move(local));
    }
    StripOptions so;
    so.gap = options.gap_mm;
    so.edge_margin = options.selvedge_margin_mm;
    so.start_margin = options.end_margin_mm;
    so.length_limit = options.max_length_mm > 0 ? options.max_length_mm - tail : 0;
    so.seed = options.seed + markers.size();
    so.threads = options.threads;
    so.workers = options.workers;
    // Share what is left of the budget among the markers still expected. A work-only budget
    // reads no clock, so the markers do not depend on how fast the machine ran.
    double expected = 1;
    if (options.max_length_mm > 0)
      expected = std::max(1.0, std::ceil(area_left / (options.fabric_width_mm * options.max_length_mm * kPlanningUtilisation)));
    const bool work_only = options.time_limit_s == 0 && options.work_limit > 0;
    if (work_only) {
      const std::uint64_t left = options.work_limit - std::min(options.work_limit, work_used);
      so.time_limit_s = 0;
      so.work_limit = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(static_cast<double>(left) / expected));
      so.improve = true;
    } else {
      const double spent = std::chrono::duration<double>(clock::now() - start).count();
      const double left = std::max(0.0, options.time_limit_s - spent);
      so.time_limit_s = left / expected;
      so.work_limit = options.work_limit ? std::max<std::uint64_t>(1, static_cast<std::uint64_t>(options.work_limit / expected)) : 0;
      so.improve = so.time_limit_s > 0;
    }
    if (options.on_work && options.work_limit > 0)
      so.on_work = [&options, work_used](std::uint64_t done, std::uint64_t) {
        options.on_work(std::min(options.work_limit, work_used + done), options.work_limit);
      };
    auto solved = nest_strip(problem, so, cancel);
    if (!solved) return std::unexpected(solved.error().with_context("nesting"));
    work_used += solved->iterations;
    if (stats) {
      stats->iterations.push_back(solved->iterations);
      stats->seconds.push_back(solved->seconds);
    }
    if (solved->placements.empty()) {
      const NestItem& it = items[origin[problem_item[solved->unplaced.front()]].nest_item];
      return fail(ErrorCode::kNesting, "nesting: piece '" + it.name + "' does not fit a marker of " +
                                           std::to_string(options.max_length_mm) + " mm");
    }
    Marker m;
    m.width_mm = options.fabric_width_mm;
    m.roll_start_mm = roll_y;
    double area = 0;
    for (const StripPlacement& p : solved->placements) {
      const int si = problem_item[p.item];
      const NestItem& it = items[origin[si].nest_item];
      --remaining[si];
      area += std::fabs(signed_area(strip_items[si].shape));
      m.placements.push_back(nesting::strip_to_roll_placement(p, it.piece));
    }
    m.length_mm = solved->length + tail;
    m.utilisation = area / (m.width_mm * m.length_mm);
    roll_y += m.length_mm;
    markers.push_back(std::move(m));
    if (solved->unplaced.empty()) break;
  }
  return markers;
}

}  // namespace tp::geometry
