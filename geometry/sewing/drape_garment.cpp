// geometry/sewing/drape_garment.cpp: the sewn garment handed to the XPBD solver with its fabric.
#include "geometry/sewing/drape_garment.h"

#include <algorithm>
#include <chrono>

#include "geometry/sewing/internal/cloth_model.h"
#include "geometry/sewing/internal/xpbd_solver.h"

namespace tp::geometry {
namespace {

/// The drape's speed limit: the travel budget per substep is at most this times the substep.
constexpr double kMaxSpeed_mm_s = 120;

}  // namespace

Result<Garment> drape_garment(const Garment& sewn, const BodySdf& body, const DrapeOptions& o, DrapeStats* stats,
                              const CancelToken* cancel) {
  const auto t0 = std::chrono::steady_clock::now();
  if (auto ok = validate_cloth_material(o.material); !ok) return fail(ok.error());
  if (o.stretch_passes < 1 || o.stretch_passes > 64)
    return fail(ErrorCode::kInvalidArgument, "drape: stretch_passes must be in [1, 64]");
  if (!(o.settle_window_s > 0)) return fail(ErrorCode::kInvalidArgument, "drape: settle_window_s must be positive");
  if (!(o.substep_s > 0 && o.substep_s <= 0.01))
    return fail(ErrorCode::kInvalidArgument, "drape: substep_s must be in (0, 0.01]");
  internal::ClothModel cloth = internal::build_cloth_model(sewn, o.material);
  internal::XpbdParams p;
  p.duration_s = o.duration_s;
  p.substep_s = o.substep_s;
  p.damping_per_s = o.damping_per_s;
  p.body_thickness_mm = o.clearance_mm;
  p.self_thickness_mm = o.self_thickness_mm;
  // A vertex moves at most 2 x max_move per substep, so two layers close by at most 0.6 x the
  // thickness in one substep and every substep pushes them apart; and no faster than 120 mm/s
  // (0.3 mm per 2.5 ms substep), whatever the substep.
  p.max_move_mm = std::min(0.15 * o.self_thickness_mm, kMaxSpeed_mm_s * o.substep_s);
  p.stretch_limit = o.material.stretch_limit;
  p.stretch_stiffness = o.material.stretch_stiffness;
  p.friction = o.material.friction;
  p.seams_after_contact = true;
  p.settle_speed_mm_s = o.settle_speed_mm_s;
  p.settle_window_s = o.settle_window_s;
  p.settle_windows = o.settle_windows;
  p.stretch_passes = o.stretch_passes;
  p.threads = o.threads;
  p.on_progress = o.on_progress;
  auto r = internal::run_xpbd(cloth, body, p, cancel);
  if (!r) return fail(r.error().with_context("drape (" + o.material.name + ")"));
  Garment g = sewn;
  g.vertices_mm = std::move(cloth.x_mm);
  if (stats) {
    stats->substeps = r->substeps;
    stats->simulated_s = r->simulated_s;
    stats->max_speed_mm_s = r->max_speed_mm_s;
    stats->settle_speed_mm_s = r->settle_speed_mm_s;
    stats->settled = r->settled;
    stats->body_contacts = r->body_contacts;
    stats->self_contacts = r->self_contacts;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return g;
}

}  // namespace tp::geometry
