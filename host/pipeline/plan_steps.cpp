// host/pipeline/plan_steps.cpp: inputs hashes of the plan steps, and loading or saving each step
// (see internal/plan_steps.h and docs/plan-storage.md).
#include "host/pipeline/internal/plan_steps.h"

#include <spdlog/spdlog.h>

#include "device/model/printer_model_file.h"
#include "host/pipeline/internal/input_hash.h"

namespace tp::host::internal {

namespace fs = std::filesystem;

namespace {

// Bumped when a plan file's meaning changes, so old plans are made again rather than misread.
constexpr const char* kPlanVersion = "tp-plan/1";

// One section of the job's manifest as canonical JSON text ("" when absent). The manifest was
// validated at intake; if it cannot be parsed now, its whole text stands in for the section.
Result<std::string> manifest_section(const Job& job, const char* section) {
  auto text = PlanStore::read(job.manifest);
  if (!text) return fail(text.error());
  auto j = nlohmann::json::parse(*text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return *text;
  if (!j.contains(section)) return std::string();
  return j[section].dump();
}

Status add_optional_file(InputHash& h, const char* label, const std::optional<fs::path>& path) {
  if (path) return h.add_file(label, *path);
  h.add(label, "none");
  return {};
}

void note(PipelineState& ps, const char* step, const std::string& what) {
  if (!ps.plan) return;
  ps.report["plan"]["dir"] = ps.plan->dir().string();
  ps.report["plan"]["steps"][step] = what;
}

std::string digest_of(const std::string& text) {
  InputHash h;
  h.add("text", text);
  return h.hex();
}

}  // namespace

Result<std::string> garment_inputs_hash(const Job& job) {
  InputHash h;
  h.add("plan", kPlanVersion);
  auto section = manifest_section(job, "garment");
  if (!section) return fail(section.error());
  h.add("garment", *section);
  // The parsed fields too, so a default the manifest leaves out still counts.
  const GarmentSpec& g = job.garment;
  h.add("sample", g.sample).add("size", g.size).add("body", g.body_kind).add("stitches", g.stitches);
  h.add("format", g.pattern_format).add("mesh_edge_mm", g.mesh_edge_mm).add("body_scale", g.body_mesh_scale_to_mm);
  for (const auto& [name, mm] : g.dress_form_mm) h.add("dress_form:" + name, mm);
  if (auto st = add_optional_file(h, "pattern_file", g.pattern); !st) return fail(st.error());
  if (auto st = add_optional_file(h, "garment_file", g.garment_mesh); !st) return fail(st.error());
  if (auto st = add_optional_file(h, "body_file", g.body_mesh); !st) return fail(st.error());
  if (auto st = add_optional_file(h, "stitches_file", g.stitches_file); !st) return fail(st.error());
  return h.hex();
}

Result<bool> find_plan_garment(PipelineState& ps) {
  auto key = garment_inputs_hash(ps.job);
  if (!key) return fail(key.error());
  ps.garment_key = *key;
  ps.plan_garment.reset();
  if (!ps.plan || ps.garment) return false;
  ps.plan_garment = ps.plan->find("garment", ps.garment_key);
  return ps.plan_garment.has_value();
}

Status load_plan_garment(PipelineState& ps, std::vector<std::vector<double>>* stitch_gaps_mm) {
  const fs::path& file = *ps.plan_garment;
  auto text = PlanStore::read(file);
  if (!text) return fail(text.error());
  bool is_3d = false;
  auto g = garment_from_text(*text, file.string(), &is_3d);
  if (!g) return fail(g.error());
  if (g->pieces.size() != ps.pattern.pieces.size())
    return fail(ErrorCode::kPipeline, file.string() + ": the stored garment has " + std::to_string(g->pieces.size()) +
                                          " pieces, the pattern " + std::to_string(ps.pattern.pieces.size()));
  for (size_t p = 0; p < g->pieces.size(); ++p)
    if (g->pieces[p].piece != static_cast<int>(p))
      return fail(ErrorCode::kPipeline, file.string() + ": stored piece " + std::to_string(p) + " is numbered " +
                                            std::to_string(g->pieces[p].piece));
  // The stitch gaps measured when the garment was sewn (its fit checks need them).
  if (auto gaps_file = ps.plan->find("stitch_gaps", ps.garment_key)) {
    auto gaps_text = PlanStore::read(*gaps_file);
    if (!gaps_text) return fail(gaps_text.error());
    auto j = nlohmann::json::parse(*gaps_text, nullptr, false);
    if (j.is_discarded() || !j.is_array())
      return fail(ErrorCode::kPipeline, gaps_file->string() + ": not a JSON array of stitch gaps");
    stitch_gaps_mm->clear();
    for (const auto& stitch : j) {
      if (!stitch.is_array()) return fail(ErrorCode::kPipeline, gaps_file->string() + ": a stitch's gaps are not an array");
      auto& out = stitch_gaps_mm->emplace_back();
      for (const auto& d : stitch) {
        if (!d.is_number()) return fail(ErrorCode::kPipeline, gaps_file->string() + ": a stitch gap is not a number");
        out.push_back(d.get<double>());
      }
    }
  }
  ps.garment = std::move(*g);
  ps.garment_is_3d = is_3d;
  ps.garment_digest = digest_of(*text);
  note(ps, "garment", "reused");
  spdlog::info("job {}: garment reused from the plan ({})", ps.options.job_id, file.string());
  return {};
}

Status save_plan_garment(PipelineState& ps, const std::vector<std::vector<double>>& stitch_gaps_mm) {
  const std::string text = garment_to_text(*ps.garment, ps.garment_is_3d);
  ps.garment_digest = digest_of(text);
  if (!ps.plan) return {};
  if (auto st = ps.plan->save("stitch_gaps", ps.garment_key, "stitch_gaps.json", nlohmann::json(stitch_gaps_mm).dump());
      !st)
    return st;
  if (auto st = ps.plan->save("garment", ps.garment_key, "garment.plan", text); !st) return st;
  note(ps, "garment", "made");
  return {};
}

namespace {

std::string marker_inputs_hash(const std::vector<geometry::NestItem>& items, const geometry::NestOptions& o) {
  InputHash h;
  h.add("plan", kPlanVersion);
  for (const auto& it : items) {
    h.add("piece", it.piece).add("name", it.name).add("quantity", it.quantity);
    h.add("rotation", static_cast<int>(it.rotation)).add("mirror", static_cast<int>(it.mirror));
    h.add("grain_x", it.grain.x).add("grain_y", it.grain.y);
    h.add("outline_points", static_cast<std::int64_t>(it.outline_mm.size()));
    for (const auto& v : it.outline_mm) h.add("x", v.x).add("y", v.y);
  }
  h.add("fabric_width_mm", o.fabric_width_mm).add("gap_mm", o.gap_mm).add("selvedge_mm", o.selvedge_margin_mm);
  h.add("end_margin_mm", o.end_margin_mm).add("max_length_mm", o.max_length_mm);
  for (const auto& d : o.defects_mm) {
    h.add("defect_points", static_cast<std::int64_t>(d.size()));
    for (const auto& v : d) h.add("x", v.x).add("y", v.y);
  }
  h.add("time_limit_s", o.time_limit_s).add("work_limit", static_cast<std::int64_t>(o.work_limit));
  h.add("seed", static_cast<std::int64_t>(o.seed)).add("threads", o.threads).add("workers", o.workers);
  return h.hex();
}

}  // namespace

Result<std::optional<std::vector<geometry::Marker>>> find_plan_markers(PipelineState& ps,
                                                                        const std::vector<geometry::NestItem>& items,
                                                                        const geometry::NestOptions& options) {
  if (!ps.plan) return std::optional<std::vector<geometry::Marker>>();
  auto file = ps.plan->find("marker", marker_inputs_hash(items, options));
  if (!file) return std::optional<std::vector<geometry::Marker>>();
  auto text = PlanStore::read(*file);
  if (!text) return fail(text.error());
  auto markers = markers_from_json(*text, file->string());
  if (!markers) return fail(markers.error());
  for (const auto& m : *markers)
    for (const auto& p : m.placements)
      if (p.piece < 0 || p.piece >= static_cast<int>(ps.pattern.pieces.size()))
        return fail(ErrorCode::kPipeline, file->string() + ": placement of piece " + std::to_string(p.piece) +
                                              ", the pattern has " + std::to_string(ps.pattern.pieces.size()));
  ps.marker_digest = digest_of(*text);
  note(ps, "marker", "reused");
  spdlog::info("job {}: marker reused from the plan ({})", ps.options.job_id, file->string());
  return std::optional<std::vector<geometry::Marker>>(std::move(*markers));
}

Status save_plan_markers(PipelineState& ps, const std::vector<geometry::NestItem>& items,
                         const geometry::NestOptions& options, const std::vector<geometry::Marker>& markers,
                         const geometry::NestStats& stats) {
  const std::string text = markers_to_json(markers, stats);
  ps.marker_digest = digest_of(text);
  if (!ps.plan) return {};
  const std::string key = marker_inputs_hash(items, options);
  if (auto st = ps.plan->save("pieces", key, "pieces.json", pieces_to_json(items)); !st) return st;
  if (auto st = ps.plan->save("marker", key, "marker.json", text); !st) return st;
  note(ps, "marker", "made");
  return {};
}

Result<SwathPlan> SwathPlan::open(PipelineState& ps, const device::PrinterModel& model, std::uint32_t first_swath) {
  SwathPlan sp;
  sp.ps_ = &ps;
  sp.first_ = first_swath;
  InputHash h;
  h.add("plan", kPlanVersion).add("garment", ps.garment_digest).add("markers", ps.marker_digest);
  for (const char* section : {"design", "finishing", "print"}) {
    auto text = manifest_section(ps.job, section);
    if (!text) return fail(text.error());
    h.add(section, *text);
  }
  for (const auto& layer : ps.job.design) {
    if (auto st = add_optional_file(h, "layer_image", layer.image); !st) return fail(st.error());
    if (auto st = add_optional_file(h, "layer_mesh", layer.mesh); !st) return fail(st.error());
  }
  if (auto st = add_optional_file(h, "icc_profile", ps.job.print.icc_profile); !st) return fail(st.error());
  if (auto st = add_optional_file(h, "calibration_profile", ps.job.print.calibration_profile); !st) return fail(st.error());
  if (auto st = add_optional_file(h, "calibration", ps.job.print.calibration); !st) return fail(st.error());
  h.add("printer_model", device::format_printer_model(model));
  sp.key_ = h.hex();
  if (!ps.plan) return sp;
  if (auto file = ps.plan->find("swaths", sp.key_)) {
    auto text = PlanStore::read(*file);
    if (!text) return fail(text.error());
    auto swaths = swaths_from_json(*text, file->string());
    if (!swaths) return fail(swaths.error());
    sp.stored_ = std::move(*swaths);
  }
  return sp;
}

Status SwathPlan::check(const device::Swath& swath) {
  PlannedSwath p = plan_swath(swath);
  if (!stored_) {
    made_.push_back(std::move(p));
    return {};
  }
  const std::string where = (ps_->plan->dir() / "swaths.json").string();
  if (p.index >= stored_->size())
    return fail(ErrorCode::kPipeline, "swath " + std::to_string(p.index) + " is not in the job's stored plan (" + where +
                                          " has " + std::to_string(stored_->size()) + " swaths)");
  if ((*stored_)[p.index].digest != p.digest)
    return fail(ErrorCode::kPipeline, "swath " + std::to_string(p.index) + " differs from the job's stored plan (" +
                                          where + "): it would not continue the fabric already printed");
  ++verified_;
  return {};
}

Status SwathPlan::finish(std::uint32_t swaths_total) {
  if (!ps_->plan) return {};
  if (stored_) {
    if (stored_->size() != swaths_total)
      return fail(ErrorCode::kPipeline, "the print made " + std::to_string(swaths_total) + " swaths, the job's stored plan " +
                                            std::to_string(stored_->size()));
    note(*ps_, "swaths", "verified " + std::to_string(verified_) + " of " + std::to_string(swaths_total));
    return {};
  }
  if (first_ != 0 || made_.size() != swaths_total) {
    note(*ps_, "swaths", "not recorded (resumed without a stored swath plan)");
    return {};
  }
  if (auto st = ps_->plan->save("swaths", key_, "swaths.json", swaths_to_json(made_)); !st) return st;
  note(*ps_, "swaths", "made");
  return {};
}

}  // namespace tp::host::internal
