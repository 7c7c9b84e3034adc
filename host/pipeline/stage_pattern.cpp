// host/pipeline/stage_pattern.cpp: the pattern stage (from a file, an OBJ garment or a project
// sample) and the mesh stage (each piece triangulated once, seams matched).
#include <cstdio>

#include "geometry/pattern/load_pattern.h"
#include "geometry/pattern/obj_garment.h"
#include "geometry/pattern/validate.h"
#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "host/pipeline/internal/plan_steps.h"

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

  nlohmann::json pieces = nlohmann::json::array();
  for (const auto& p : ps.pattern.pieces) pieces.push_back(p.name);
  ps.report["pattern"] = {{"name", ps.pattern.name},
                          {"size", ps.pattern.size},
                          {"piece_count", ps.pattern.pieces.size()},
                          {"pieces", pieces},
                          {"stitch_count", ps.pattern.stitches.size()}};
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
