// geometry/nesting/strip_nester.cpp: nest_strip(): validates the instance, prepares collision
// shapes, runs the constructive placement and the improving search, and reports the result.
#include "geometry/nesting/strip_nester.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "geometry/nesting/internal/constructive.h"
#include "geometry/nesting/internal/layout.h"
#include "geometry/nesting/internal/separator.h"
#include "geometry/nesting/internal/shape_prep.h"
#include "geometry/nesting/internal/strip_search.h"

namespace tp::geometry {
namespace {

using namespace nesting;

// Every collision outline is grown by this fraction of the instance size beyond the clearance, so
// that floating-point rounding can never turn a legal layout into one with a sliver of overlap.
constexpr double kSafetyClearanceRel = 1e-7;
// Sides of the polygon standing in for the disc when growing outlines by a real gap.
constexpr int kGapDiscSides = 16;
// Angular step when checking that a freely rotating item fits the width at some angle.
constexpr int kFreeFitSteps = 360;
// Sampling of the constructive placement.
constexpr SampleConfig kConstructiveSamples{200, 0, 3};

std::shared_ptr<spdlog::logger> logger() {
  auto l = spdlog::get("geometry");
  return l ? l : spdlog::default_logger();
}

std::string item_name(const StripItem& item, size_t index) {
  if (!item.name.empty()) return item.name;
  return "item " + std::to_string(index) + " (id " + std::to_string(item.id) + ")";
}

Result<ItemShape> prepare_shape(const Polygon& raw, const std::string& what, double grow, int sides,
                                double simplify_tolerance) {
  auto cleaned = nesting::clean_polygon(raw, what);
  if (!cleaned) return std::unexpected(cleaned.error());
  ItemShape s;
  s.original = *cleaned;
  s.area = signed_area(s.original);
  s.outline = inflate_polygon(s.original, grow, sides);
  s.outline = simplify_outward(s.outline, simplify_tolerance * s.area);
  s.poles = compute_poles(s.outline);
  s.hull_area = convex_hull_area(s.outline);
  s.diameter = point_set_diameter(s.outline);
  return s;
}

Status check_options(const StripProblem& p, const StripOptions& o) {
  auto bad = [](const std::string& m) { return fail(ErrorCode::kInvalidArgument, m); };
  if (!(p.width > 0) || !std::isfinite(p.width)) return bad("strip width must be a positive number");
  if (!(o.gap >= 0) || !std::isfinite(o.gap)) return bad("gap must be >= 0");
  if (!(o.edge_margin >= 0) || !(o.start_margin >= 0)) return bad("margins must be >= 0");
  if (2 * o.edge_margin >= p.width) return bad("edge margins leave no strip width");
  if (!(o.length_limit >= 0)) return bad("length limit must be >= 0");
  if (!(o.time_limit_s >= 0)) return bad("time limit must be >= 0");
  if (o.threads < 1 || o.workers < 1) return bad("threads and workers must be >= 1");
  if (!(o.explore_fraction >= 0 && o.explore_fraction <= 1)) return bad("explore fraction must be in [0, 1]");
  if (p.items.empty()) return bad("no items to nest");
  for (size_t i = 0; i < p.items.size(); ++i) {
    const StripItem& it = p.items[i];
    if (it.demand < 0) return bad(item_name(it, i) + ": demand must be >= 0");
    if (it.poses.empty()) return bad(item_name(it, i) + ": no allowed pose");
    for (const StripPose& q : it.poses)
      if (!std::isfinite(q.rotation_deg)) return bad(item_name(it, i) + ": rotation is not a number");
  }
  return {};
}

// Builds the immutable context: collision shapes, posed shapes, copies and hazards.
Result<std::unique_ptr<NestContext>> build_context(const StripProblem& p, const StripOptions& o) {
  auto ctx = std::make_unique<NestContext>();
  double scale = p.width;
  for (const StripItem& it : p.items)
    for (Vec2 v : it.shape) scale = std::max({scale, std::fabs(v.x), std::fabs(v.y)});
  const double grow = o.gap / 2 + kSafetyClearanceRel * scale;
  const int sides = o.gap > 0 ? kGapDiscSides : 4;
  ctx->x_lo = o.start_margin - o.gap / 2;
  ctx->y_lo = o.edge_margin - o.gap / 2;
  ctx->y_hi = p.width - o.edge_margin + o.gap / 2;
  const double usable = ctx->y_hi - ctx->y_lo;
  for (size_t i = 0; i < p.items.size(); ++i) {
    const StripItem& it = p.items[i];
    auto shape = prepare_shape(it.shape, item_name(it, i), grow, sides, o.simplify_tolerance);
    if (!shape) return std::unexpected(shape.error());
    std::vector<Pose> poses;
    std::vector<double> degrees;
    std::vector<OrientedShape> oriented;
    bool fits = false;
    for (const StripPose& q : it.poses) {
      Pose pose{static_cast<int>(poses.size()), (it.free_rotation ? 0.0 : q.rotation_deg) * std::numbers::pi / 180,
                q.mirror};
      OrientedShape os = orient(*shape, pose);
      if (it.free_rotation) {
        for (int s = 0; s < kFreeFitSteps && !fits; ++s)
          fits = orient(*shape, Pose{-1, 2 * std::numbers::pi * s / kFreeFitSteps, q.mirror}).box.height() <= usable;
      } else if (os.box.height() > usable) {
        continue;  // this pose does not fit across the strip
      }
      fits = true;
      poses.push_back(pose);
      degrees.push_back(q.rotation_deg);
      oriented.push_back(std::move(os));
    }
    if (!fits || poses.empty())
      return fail(ErrorCode::kNesting, item_name(it, i) + " does not fit the strip width in any allowed pose");
    ctx->shapes.push_back(std::move(*shape));
    ctx->poses.push_back(std::move(poses));
    ctx->pose_degrees.push_back(std::move(degrees));
    ctx->oriented.push_back(std::move(oriented));
    ctx->free_rotation.push_back(it.free_rotation);
    for (int c = 0; c < it.demand; ++c) ctx->copy_type.push_back(static_cast<int>(i));
  }
  for (size_t h = 0; h < p.hazards.size(); ++h) {
    auto shape = prepare_shape(p.hazards[h], "hazard " + std::to_string(h), grow, sides, 0.0);
    if (!shape) return std::unexpected(shape.error());
    ctx->hazards.push_back(std::move(*shape));
  }
  return ctx;
}

// The pose of a copy in the caller's terms (the exact degrees given for discrete poses).
StripPlacement to_placement(const StripProblem& p, const NestContext& ctx, const Placed& placed, int type) {
  StripPlacement out;
  out.item = type;
  out.item_id = p.items[type].id;
  out.mirror = placed.pose.mirror;
  if (placed.pose.index >= 0 && !ctx.free_rotation[type]) {
    out.rotation_deg = ctx.pose_degrees[type][placed.pose.index];
  } else {
    double deg = std::fmod(placed.pose.angle_rad * 180 / std::numbers::pi, 360.0);
    out.rotation_deg = deg < 0 ? deg + 360 : deg;
  }
  out.translation = placed.t;
  return out;
}

}  // namespace

Polygon place_polygon(const Polygon& shape, const StripPlacement& placement) {
  const Affine2 m = Affine2::translation(placement.translation)
                        .compose(Affine2::rotation_deg(placement.rotation_deg))
                        .compose(placement.mirror ? Affine2::scale(-1, 1) : Affine2{});
  Polygon out;
  out.reserve(shape.size());
  for (Vec2 v : shape) out.push_back(m.apply(v));
  return out;
}

Result<StripSolution> nest_strip(const StripProblem& problem, const StripOptions& options, const CancelToken& cancel) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  if (auto ok = check_options(problem, options); !ok) return std::unexpected(ok.error());
  auto built = build_context(problem, options);
  if (!built) return std::unexpected(built.error().with_context("strip '" + problem.name + "'"));
  const NestContext& ctx = **built;

  Rng rng(options.seed);
  const double big_length = [&] {
    double s = 0;
    for (int t : ctx.copy_type) s += ctx.shapes[t].diameter;
    return ctx.x_lo + 2 * s + 1;
  }();
  const double x_limit = options.length_limit > 0 ? options.length_limit + options.gap / 2 : big_length;
  Layout layout(&ctx, big_length);
  const auto time_limit = std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(options.time_limit_s));
  const auto deadline = start + time_limit;
  // A work budget with no time limit reads no clock: the layout depends on the inputs alone.
  const bool timed = !(options.time_limit_s == 0 && options.work_limit > 0);
  auto stop = [&] { return cancel.cancelled(); };
  const std::vector<int> unplaced = construct_layout(layout, x_limit, kConstructiveSamples, rng, stop);
  if (cancel.cancelled()) return fail(ErrorCode::kCancelled, "strip '" + problem.name + "': nesting cancelled");

  QueryScratch scratch;
  fit_strip(layout, scratch);
  StripSolution sol;
  sol.constructive_length = layout.used_original_x_hi();
  std::uint64_t work = 0;
  const bool any_placed = static_cast<int>(unplaced.size()) < layout.size();
  if (options.improve && any_placed && layout.size() > 1) {
    ThreadPool team(std::max(1, options.threads));
    Separator sep(options.workers, &team);
    StripSearchConfig cfg;
    const double area_total = [&] {
      double a = 0;
      for (int k = 0; k < layout.size(); ++k)
        if (layout.item(k).present) a += ctx.shapes[ctx.copy_type[k]].area;
      return a;
    }();
    const auto hook = [&](const Layout& l) {
      if (options.on_improvement) {
        const double len = l.used_original_x_hi();
        options.on_improvement(len, area_total / (problem.width * len),
                               std::chrono::duration<double>(clock::now() - start).count());
      }
    };
    // Work progress at each whole percent of the work limit: a bounded number of calls.
    std::uint64_t reported_percent = 0;
    const std::function<void()> work_hook = [&] {
      const std::uint64_t percent = std::min<std::uint64_t>(100, work * 100 / options.work_limit);
      if (percent == reported_percent) return;
      reported_percent = percent;
      options.on_work(work, options.work_limit);
    };
    const std::function<void()>* on_work = options.on_work && options.work_limit > 0 ? &work_hook : nullptr;
    const auto split = start + std::chrono::duration_cast<clock::duration>(time_limit * options.explore_fraction);
    const auto explore_work = static_cast<std::uint64_t>(static_cast<double>(options.work_limit) * options.explore_fraction);
    Budget b1{start, split,  options.work_limit ? std::max<std::uint64_t>(explore_work, 1) : 0, &work, 0, &cancel,
              timed, on_work};
    SearchStats stats;
    explore(layout, sep, cfg, b1, rng, hook, stats);
    Budget b2{split, deadline, options.work_limit ? std::max<std::uint64_t>(options.work_limit - explore_work, 1) : 0,
              &work, work,     &cancel,
              timed, on_work};
    if (timed && b2.start < clock::now()) b2.start = clock::now();
    compress(layout, sep, cfg, b2, rng, hook, stats);
    sol.explore_feasible = stats.explore_feasible;
    sol.explore_failed = stats.explore_failed;
    sol.compress_feasible = stats.compress_feasible;
    sol.compress_failed = stats.compress_failed;
    sol.evaluations = static_cast<std::uint64_t>(sep.evaluations());
    logger()->debug("nest '{}': {} separator iterations, {} evaluations", problem.name, work, sol.evaluations);
  }

  for (int k = 0; k < layout.size(); ++k)
    if (layout.item(k).present) sol.placements.push_back(to_placement(problem, ctx, layout.item(k), ctx.copy_type[k]));
  for (int k : unplaced) sol.unplaced.push_back(ctx.copy_type[k]);
  double area = 0;
  for (int k = 0; k < layout.size(); ++k)
    if (layout.item(k).present) area += ctx.shapes[ctx.copy_type[k]].area;
  sol.length = any_placed ? layout.used_original_x_hi() : 0;
  sol.density = sol.length > 0 ? area / (problem.width * sol.length) : 0;
  sol.iterations = work;
  sol.seconds = std::chrono::duration<double>(clock::now() - start).count();
  return sol;
}

}  // namespace tp::geometry
