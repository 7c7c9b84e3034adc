// host/pipeline/stage_pattern.cpp: the pattern stage (from a file, an OBJ garment or a project
// sample) and the mesh stage (each piece triangulated once, seams matched).
#include <algorithm>
#include <cstdio>

#include "geometry/pattern/import/load_pattern.h"
#include "geometry/pattern/import/obj_garment.h"
#include "geometry/pattern/stitches_json.h"
#include "geometry/pattern/suggest_stitches.h"
#include "geometry/pattern/validate.h"
#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/plan_steps.h"
#include "host/pipeline/job_stitch_check.h"

namespace tp::host::internal {

namespace {

// Measurements for the job: its size, then any dress-form measurements it gives.
Result<geometry::BodyMeasurements> job_measurements(const Job& job) {
  auto base = geometry::samples::parse_size(job.garment.size);
  if (!base) return fail(ErrorCode::kValidation, "job.json: /garment/size: " + base.error().message);
  if (job.garment.dress_form_mm.empty()) return *base;
  std::string text;
  for (const auto& [name, mm] : job.garment.dress_form_mm) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%s=%.3f", text.empty() ? "" : ",", name.c_str(), mm);
    text += buf;
  }
  auto m = geometry::parse_measurements(text, *base);
  if (!m) return fail(ErrorCode::kValidation, "job.json: /garment/body/dress_form: " + m.error().message);
  if (auto st = geometry::validate(*m); !st)
    return fail(ErrorCode::kValidation, "job.json: /garment/body/dress_form: " + st.error().message);
  return *m;
}

Error from_geometry(const geometry::Error& e) { return Error{ErrorCode::kPipeline, e.message}; }

// Stitches a job adds to its pattern's (a stitches file, suggestions) may be eased up to the
// suggestions' own limit; the pattern's own stitches are held to the default tolerance.
geometry::ValidationOptions added_stitch_tolerance() {
  geometry::ValidationOptions o;
  o.stitch_length_tolerance_ratio = std::max(geometry::SuggestOptions{}.max_ease_ratio, geometry::SuggestOptions{}.length_tolerance_ratio);
  return o;
}

// The job's stitches file, then suggestions for the edges still free ("stitches": "suggest").
// Records each stitch's source in ps.stitch_sources (index-aligned with pattern.stitches).
Status add_job_stitches(PipelineState& ps) {
  const GarmentSpec& g = ps.job.garment;
  ps.stitch_sources.assign(ps.pattern.stitches.size(), nlohmann::json{{"source", "pattern"}});
  if (g.stitches_file) {
    auto st = geometry::load_stitches_json(*g.stitches_file, ps.pattern);
    if (!st) return fail(Error{ErrorCode::kValidation, st.error().message}.with_context("job.json: /garment/stitches_file"));
    for (auto& s : *st) {
      ps.pattern.stitches.push_back(s);
      ps.stitch_sources.push_back({{"source", "job"}, {"file", g.stitches_file->filename().string()}});
    }
  }
  if (g.stitches == "suggest") {
    geometry::SuggestOptions opt;
    opt.min_score = g.suggest_min_score;
    for (const auto& s : geometry::suggest_stitches(ps.pattern, opt))
      for (const auto& st : s.stitches) {
        ps.pattern.stitches.push_back(st);
        ps.stitch_sources.push_back({{"source", "suggested"}, {"score", s.score}, {"reason", s.reason}});
      }
  }
  return {};
}

}  // namespace

Status stage_pattern(PipelineState& ps) {
  const GarmentSpec& g = ps.job.garment;
  if (!g.sample.empty() || g.body_kind == "dress_form") {
    auto m = job_measurements(ps.job);
    if (!m) return fail(m.error());
    ps.measurements = *m;
  }
  if (!g.sample.empty()) {
    auto pat = geometry::samples::draft_garment(g.sample, *ps.measurements, g.size);
    if (!pat) return fail(from_geometry(pat.error()).with_context("sample garment '" + g.sample + "'"));
    ps.pattern = std::move(*pat);
  } else if (g.garment_mesh) {
    auto obj = geometry::load_obj_garment(*g.garment_mesh);
    if (!obj) return fail(from_geometry(obj.error()));
    ps.pattern = std::move(obj->pattern);
    ps.garment = std::move(obj->garment);
    ps.garment_is_3d = true;
  } else {
    geometry::PatternImportOptions opt;
    auto pat = geometry::load_pattern(*g.pattern, opt);
    if (!pat) return fail(from_geometry(pat.error()));
    ps.pattern = std::move(*pat);
  }
  if (auto st = geometry::validate_pattern(ps.pattern); !st)
    return fail(from_geometry(st.error()).with_context("pattern"));
  const std::size_t own_stitches = ps.pattern.stitches.size();
  if (!g.garment_mesh) {
    if (auto st = add_job_stitches(ps); !st) return st;
    if (ps.pattern.stitches.size() > own_stitches)
      if (auto st = geometry::validate_pattern(ps.pattern, added_stitch_tolerance()); !st)
        return fail(Error{ErrorCode::kValidation, st.error().message}.with_context("pattern with the job's stitches"));
  }
  // A body asks for a sewn garment: a pattern with nothing to sew would only wrap pieces round it.
  if (g.body_kind != "none" && !g.garment_mesh && g.sample.empty() && ps.pattern.stitches.empty())
    return fail(ErrorCode::kValidation, no_stitches_message(g, ps.pattern.name));

  nlohmann::json pieces = nlohmann::json::array();
  for (const auto& p : ps.pattern.pieces) pieces.push_back(p.name);
  ps.report["pattern"] = {{"name", ps.pattern.name},
                          {"size", ps.pattern.size},
                          {"piece_count", ps.pattern.pieces.size()},
                          {"pieces", pieces},
                          {"stitch_count", ps.pattern.stitches.size()},
                          {"own_stitch_count", own_stitches}};
  ps.report["piece_count"] = ps.pattern.pieces.size();
  return {};
}

Status stage_mesh(PipelineState& ps) {
  // A garment stored in the job's plan for these inputs needs no mesh: its charts are the mesh.
  auto stored = find_plan_garment(ps);
  if (!stored) return fail(stored.error());
  if (*stored) {
    ps.report["mesh"] = {{"source", "plan"}};
    ps.stage_reused = true;
    return {};
  }
  if (ps.garment) {
    ps.report["mesh"] = {{"source", "garment_mesh"}};
    return {};
  }
  geometry::TriangulateOptions opt;
  opt.target_edge_mm = ps.job.garment.mesh_edge_mm;
  auto meshes = geometry::mesh_pattern(ps.pattern, opt);
  if (!meshes) return fail(from_geometry(meshes.error()));
  std::size_t vertices = 0, triangles = 0;
  for (const auto& m : meshes->pieces) {
    vertices += m.vertices_mm.size();
    triangles += m.triangles.size();
  }
  ps.meshes = std::move(*meshes);
  ps.report["mesh"] = {{"target_edge_mm", opt.target_edge_mm}, {"vertices_2d", vertices}, {"triangles", triangles}};
  return {};
}

}  // namespace tp::host::internal
