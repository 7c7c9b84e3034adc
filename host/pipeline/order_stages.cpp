// host/pipeline/order_stages.cpp: an order job's pattern, mesh, garment and design stages: each
// size drafted, meshed and sewn once, the design re-projected from the base size, one renderer
// per copy (its text and labels), and all pieces merged into one pattern for the marker.
#include <cctype>
#include <cmath>

#include "geometry/continuity/continuity.h"
#include "host/pipeline/internal/order_run.h"
#include "host/pipeline/order_copy_renderer.h"
#include "host/pipeline/order_renderer.h"
#include "host/pipeline/order_reprojection.h"
#include "host/pipeline/order_stroke_mapping.h"

namespace tp::host::internal {

namespace {

// Around a copy's text and labels its overlay keeps this much of the garment: exact down to
// pixels of a third of it (every print and preview resolution the job writes).
constexpr double kOverlayMarginMm = 5;

std::string stem_of(const std::string& size) {
  std::string out;
  for (char c : size) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return out.empty() ? "size" : out;
}

// A sub-stage's failure, naming the size (and copy).
Status in_size(Status st, const OrderSizeRun& s) {
  if (st) return st;
  return fail(st.error().with_context("order size '" + s.spec.size + "'"));
}

// Runs `fn` on every size's state, stopping at the first failure.
template <class Fn>
Status each_size(PipelineState& ps, Fn fn) {
  for (auto& s : ps.order->sizes) {
    if (ps.cancel.cancelled()) return fail(ErrorCode::kCancelled, "job cancelled");
    if (auto st = in_size(fn(*s->ps), *s); !st) return st;
  }
  return {};
}

nlohmann::json stats_json(const geometry::DeltaEStats& s) {
  if (s.samples == 0) return {{"samples", 0}, {"de00_mean", nullptr}, {"de00_p95", nullptr}, {"de00_max", nullptr}};
  return {{"samples", s.samples}, {"de00_mean", s.mean}, {"de00_p95", s.p95}, {"de00_max", s.max}};
}

// Where the base design's planar and text layers land in this size: the mapped centre against
// the size's own centre-front bust point plus the base's offset from its bust point.
nlohmann::json reprojection_json(const std::vector<DesignLayerSpec>& base_layers,
                                 const std::vector<DesignLayerSpec>& layers, const SizeMapping* map) {
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < layers.size(); ++i) {
    const DesignLayerSpec& b = base_layers[i];
    const DesignLayerSpec& l = layers[i];
    nlohmann::json e = {{"layer", b.name.empty() ? b.type + "-" + std::to_string(i) : b.name}, {"type", b.type}};
    if (b.type == "planar" || b.type == "text") {
      e["centre_mm"] = l.centre_mm;
      e["width_mm"] = b.type == "planar" ? l.width_mm : l.text_size_mm;
      e["size_ratio"] =
          b.type == "planar" ? (b.width_mm > 0 ? l.width_mm / b.width_mm : 1.0) : l.text_size_mm / b.text_size_mm;
      if (map && b.normal[2] > 0.5) {
        // Front-facing layers against the nearer (in height) of the centre-front bust and hip
        // points: the landmark check holds in placement "body"; in "graded" the offset scales.
        const geometry::Vec3 base_bust = centre_front_bust_point(map->base_measurements());
        const geometry::Vec3 base_hip = centre_front_hip_point(map->base_measurements());
        const bool hip = std::abs(b.centre_mm[1] - base_hip.y) < std::abs(b.centre_mm[1] - base_bust.y);
        const geometry::Vec3 bb = hip ? base_hip : base_bust;
        const geometry::Vec3 tb = hip ? centre_front_hip_point(map->target_measurements())
                                      : centre_front_bust_point(map->target_measurements());
        const geometry::Vec3 off{b.centre_mm[0] - bb.x, b.centre_mm[1] - bb.y, b.centre_mm[2] - bb.z};
        const geometry::Vec3 want = tb + off;
        const geometry::Vec3 got{l.centre_mm[0], l.centre_mm[1], l.centre_mm[2]};
        e["landmark"] = hip ? "centre-front hip point" : "centre-front bust point";
        e[hip ? "hip_point_mm" : "bust_point_mm"] = {tb.x, tb.y, tb.z};
        e[hip ? "offset_from_hip_point_mm" : "offset_from_bust_point_mm"] = {off.x, off.y, off.z};
        e["landmark_error_mm"] = geometry::norm(got - want);
      }
    } else if (b.type == "cylindrical") {
      e["tile_width_mm"] = l.tile_width_mm;
      e["tile_height_mm"] = l.tile_height_mm;
      if (l.axis_origin_mm) e["axis_origin_mm"] = *l.axis_origin_mm;
    } else if (b.type == "stroke") {
      e["points_mm"] = l.points_mm;
      e["radius_mm"] = l.radius_mm;
    }
    out.push_back(std::move(e));
  }
  return out;
}

// Index of the first personalised layer (a text layer taking fields from the copies); the
// layer count when none is.
size_t personal_top_layers(const std::vector<DesignLayerSpec>& design) {
  for (size_t i = 0; i < design.size(); ++i)
    if (design[i].type == "text" && !template_fields(design[i].text).empty()) return i;
  return design.size();
}

// Whether every layer from `first` up is personalised (they can then be drawn over the rest).
bool all_personal_from(const std::vector<DesignLayerSpec>& design, size_t first) {
  for (size_t i = first; i < design.size(); ++i)
    if (design[i].type != "text" || template_fields(design[i].text).empty()) return false;
  return true;
}

// The renderer of a size's layers below the copies' text, without printed labels (each copy
// prints its own), shared by all the size's copies. `design_report` gets its layer names.
[[nodiscard]] Result<std::shared_ptr<const geometry::PieceRenderer>> build_size_base(
    const OrderSizeRun& s, std::vector<DesignLayerSpec> layers, const geometry::CancelToken& cancel,
    nlohmann::json& design_report) {
  Job job = s.job;
  job.design = std::move(layers);
  if (job.finishing.labels == "inside") job.finishing.labels = "none";
  nlohmann::json report = nlohmann::json::object();
  PipelineState bps(job, s.options, cancel, report);
  bps.pattern = s.ps->pattern;
  bps.garment = s.ps->garment;
  bps.garment_is_3d = s.ps->garment_is_3d;
  bps.body = s.ps->body;
  bps.measurements = s.ps->measurements;
  if (auto st = stage_design(bps); !st) return fail(st.error().with_context("shared layers"));
  design_report = report["design"];
  return std::shared_ptr<const geometry::PieceRenderer>(std::move(bps.renderer));
}

// Maps every stroke layer of the base design onto size `s` through the pieces under its points
// (order_stroke_mapping.h), writing the points into `layers` and how they were mapped to `notes`.
void map_strokes_through_pieces(const std::vector<DesignLayerSpec>& design, const OrderSizeRun& base,
                                const OrderSizeRun& s, std::vector<DesignLayerSpec>& layers,
                                std::vector<nlohmann::json>& notes) {
  if (!base.ps->garment || !s.ps->garment || !base.ps->garment_is_3d || !s.ps->garment_is_3d) return;
  for (size_t i = 0; i < design.size(); ++i) {
    if (design[i].type != "stroke") continue;
    std::vector<geometry::Vec3> pts;
    for (const auto& p : design[i].points_mm) pts.push_back({p[0], p[1], p[2]});
    std::string why;
    auto mapped =
        map_stroke_through_pieces(pts, {&base.ps->pattern, &*base.ps->garment}, {&s.ps->pattern, &*s.ps->garment}, why);
    if (!mapped) {
      notes[i] = {{"mapped_through", "body"}, {"pieces_not_used_because", why}};
      continue;
    }
    nlohmann::json pieces = nlohmann::json::array();
    for (size_t k = 0; k < mapped->size(); ++k) {
      const geometry::Vec3 q = (*mapped)[k].point_mm;
      layers[i].points_mm[k] = {q.x, q.y, q.z};
      pieces.push_back((*mapped)[k].piece);
    }
    notes[i] = {{"mapped_through", "pieces"}, {"point_pieces", pieces}};
  }
}

}  // namespace

Status stage_order_pattern(PipelineState& ps) {
  const OrderSpec& order = *ps.job.order;
  ps.order = std::make_shared<OrderRun>();
  for (size_t i = 0; i < order.sizes.size(); ++i) {
    auto s = std::make_unique<OrderSizeRun>();
    s->spec = order.sizes[i];
    s->stem = stem_of(s->spec.size);
    s->job = ps.job;
    s->job.order.reset();
    s->job.garment.size = s->spec.size;
    if (s->spec.pattern) s->job.garment.pattern = s->spec.pattern;
    if (!s->spec.dress_form_mm.empty()) s->job.garment.dress_form_mm = s->spec.dress_form_mm;
    s->options.out_dir = ps.options.out_dir / "sizes" / s->stem;
    std::error_code ec;
    std::filesystem::create_directories(s->options.out_dir, ec);
    if (ec) return fail(ErrorCode::kIo, s->options.out_dir.string() + ": " + ec.message());
    s->options.job_id = ps.options.job_id;
    s->ps = std::make_unique<PipelineState>(s->job, s->options, ps.cancel, s->report);
    if (s->spec.size == order.base_size) ps.order->base = i;
    ps.order->sizes.push_back(std::move(s));
  }
  if (auto st = each_size(ps, stage_pattern); !st) return st;
  const OrderSizeRun& base = *ps.order->sizes[ps.order->base];
  // The order's pattern until the design stage merges every copy: the base size's.
  ps.pattern = base.ps->pattern;
  ps.measurements = base.ps->measurements;
  ps.report["pattern"] = base.report["pattern"];
  ps.report["pattern"]["size"] = nullptr;
  ps.report["pattern"]["sizes"] = nlohmann::json::array();
  for (const auto& s : ps.order->sizes) ps.report["pattern"]["sizes"].push_back(s->spec.size);
  return {};
}

Status stage_order_mesh(PipelineState& ps) {
  if (auto st = each_size(ps, stage_mesh); !st) return st;
  nlohmann::json per = nlohmann::json::object();
  for (const auto& s : ps.order->sizes) per[s->spec.size] = s->report["mesh"];
  ps.report["mesh"] = {{"source", "order"}, {"sizes", per}};
  return {};
}

Status stage_order_garment(PipelineState& ps) {
  // Each size is sewn (and draped) once, whatever its quantity: its copies share the garment.
  if (auto st = each_size(ps, stage_garment); !st) return st;
  const OrderSizeRun& base = *ps.order->sizes[ps.order->base];
  ps.report["garment"] = base.report["garment"];
  ps.report["garment"]["size"] = base.spec.size;
  ps.garment_is_3d = base.ps->garment_is_3d;
  ps.body = base.ps->body;
  std::string digests;
  for (const auto& s : ps.order->sizes) digests += s->ps->garment_digest;
  ps.garment_digest = digests;
  return {};
}

Status stage_order_design(PipelineState& ps) {
  const OrderSpec& order = *ps.job.order;
  OrderRun& run = *ps.order;
  const OrderSizeRun& base = *run.sizes[run.base];
  const bool graded = order.placement == "graded";
  const int total = order.garments();

  ps.pattern = {};
  ps.pattern.name = base.ps->pattern.name;
  ps.pattern.size = "order";
  ps.garment = geometry::Garment{};
  ps.stitch_sources.clear();
  std::vector<OrderPiece> pieces;
  nlohmann::json sizes = nlohmann::json::array(), copies = nlohmann::json::array();
  int copy_no = 0;
  // Copies are personalised when a text layer takes fields from them. When those layers are the
  // design's top layers, each size renders the others once (its base) and every copy adds only
  // its text and labels over it; otherwise each copy has a renderer of all layers.
  const size_t top = personal_top_layers(ps.job.design);
  const bool personal = top < ps.job.design.size();
  const bool layered = personal && top > 0 && all_personal_from(ps.job.design, top);
  double x_offset_mm = 0;
  for (size_t si = 0; si < run.sizes.size(); ++si) {
    OrderSizeRun& s = *run.sizes[si];
    // The base design carried onto this size through the dress forms of both.
    std::optional<SizeMapping> map;
    std::vector<DesignLayerSpec> layers = ps.job.design;
    if (si != run.base && base.ps->measurements && s.ps->measurements) {
      map.emplace(*base.ps->measurements, *s.ps->measurements, graded);
      layers = reproject_layers(ps.job.design, *map);
    }
    // Strokes go through the pieces they lie on (pattern position graded to this size's piece),
    // so they cross the same seams; the body mapping above stays where that is not possible.
    std::vector<nlohmann::json> stroke_notes(layers.size());
    if (si != run.base) map_strokes_through_pieces(ps.job.design, base, s, layers, stroke_notes);
    nlohmann::json size_report = {{"size", s.spec.size},
                                  {"quantity", s.spec.quantity},
                                  {"base", si == run.base},
                                  {"pattern", s.report["pattern"]},
                                  {"garment", s.report["garment"]},
                                  {"files_dir", "sizes/" + s.stem},
                                  {"copies", nlohmann::json::array()}};
    if (s.report.contains("sewing")) size_report["sewing"] = s.report["sewing"];
    // The base size reports its own landmarks too (an identity mapping), so every size can be checked.
    std::optional<SizeMapping> identity;
    if (si == run.base && base.ps->measurements)
      identity.emplace(*base.ps->measurements, *base.ps->measurements, graded);
    const SizeMapping* report_map = map ? &*map : identity ? &*identity : nullptr;
    size_report["reprojection"] = {{"placement", map ? order.placement : (si == run.base ? "base" : "unmapped")},
                                   {"layers", reprojection_json(ps.job.design, layers, report_map)}};
    for (size_t i = 0; i < stroke_notes.size(); ++i)
      if (!stroke_notes[i].is_null()) size_report["reprojection"]["layers"][i].update(stroke_notes[i]);
    std::shared_ptr<OrderCopyRun> first;
    std::shared_ptr<const geometry::PieceRenderer> size_renderer;
    std::shared_ptr<const geometry::PieceRenderer> base_renderer;
    nlohmann::json base_design_report;
    if (layered) {
      auto b = build_size_base(s, std::vector<DesignLayerSpec>(layers.begin(), layers.begin() + static_cast<long>(top)),
                               ps.cancel, base_design_report);
      if (!b) return fail(b.error().with_context("order size '" + s.spec.size + "'"));
      base_renderer = std::move(*b);
    }
    for (int q = 0; q < s.spec.quantity; ++q) {
      auto c = std::make_shared<OrderCopyRun>();
      c->copy = ++copy_no;
      c->size = si;
      if (!order.copies.empty()) c->fields = order.copies[static_cast<size_t>(c->copy - 1)];
      c->job = s.job;
      c->job.name = ps.job.name + " " + std::to_string(c->copy) + "/" + std::to_string(total);
      std::vector<DesignLayerSpec> filled = layers;
      for (DesignLayerSpec& l : filled)
        if (l.type == "text") l.text = fill_template(l.text, c->fields);
      // A layered copy builds only its text layers (over the size's base).
      c->job.design = filled;
      if (layered) c->job.design.erase(c->job.design.begin(), c->job.design.begin() + static_cast<long>(top));
      std::shared_ptr<const geometry::PieceRenderer> renderer;
      if (first && !personal) {
        // Copies that differ in nothing print the same pieces: they share the size's renderer
        // (its labels name the size and the job; the marker and cut files name each copy).
        c->job.name = first->job.name;
        c->ps = std::make_unique<PipelineState>(c->job, s.options, ps.cancel, c->report);
        c->ps->finishing = first->ps->finishing;
        c->report["design"] = first->report["design"];
        renderer = size_renderer;
      } else {
        if (!personal) c->job.name = ps.job.name;
        c->ps = std::make_unique<PipelineState>(c->job, s.options, ps.cancel, c->report);
        c->ps->pattern = s.ps->pattern;
        c->ps->garment = s.ps->garment;
        c->ps->garment_is_3d = s.ps->garment_is_3d;
        c->ps->body = s.ps->body;
        c->ps->measurements = s.ps->measurements;
        // A layered copy's renderer holds only the region its text and labels print on.
        if (layered) c->ps->overlay_margin_mm = kOverlayMarginMm;
        if (auto st = stage_design(*c->ps); !st)
          return fail(st.error().with_context("order size '" + s.spec.size + "' copy " + std::to_string(c->copy)));
        renderer = std::shared_ptr<const geometry::PieceRenderer>(std::move(c->ps->renderer));
        c->ps->design = {};  // the renderer holds what it samples
        c->ps->renderer_base.reset();
        if (layered) {
          renderer = std::make_shared<OrderCopyRenderer>(base_renderer, renderer);
          // The copy prints every layer: the base's, then its own.
          nlohmann::json names = base_design_report["layers"];
          for (const auto& n : c->report["design"]["layers"]) names.push_back(n);
          c->report["design"]["layers"] = std::move(names);
        }
        // The copy's own pattern and garment are no longer needed: the renderer keeps what it samples.
        size_renderer = renderer;
      }
      // Merge: this copy's pieces (renamed "<piece>.<size>.<copy>"), stitches and 3D garment.
      const int first_piece = static_cast<int>(ps.pattern.pieces.size());
      const int first_vertex = static_cast<int>(ps.garment->vertices_mm.size());
      c->first_piece = first_piece;
      c->x_offset_mm = x_offset_mm;
      nlohmann::json names = nlohmann::json::array();
      for (size_t k = 0; k < s.ps->pattern.pieces.size(); ++k) {
        geometry::Piece p = s.ps->pattern.pieces[k];
        p.name += "." + s.stem + "." + std::to_string(c->copy);
        c->piece_names.push_back(p.name);
        names.push_back(p.name);
        ps.pattern.pieces.push_back(std::move(p));
        pieces.push_back({renderer, static_cast<int>(k)});
      }
      for (geometry::Stitch st : s.ps->pattern.stitches) {
        st.a.piece += first_piece;
        st.b.piece += first_piece;
        ps.pattern.stitches.push_back(st);
      }
      for (const auto& w : s.ps->pattern.warnings)
        if (q == 0) ps.pattern.warnings.push_back("size " + s.spec.size + ": " + w);
      for (const auto& src : s.ps->stitch_sources) ps.stitch_sources.push_back(src);
      for (const geometry::Vec3& v : s.ps->garment->vertices_mm)
        ps.garment->vertices_mm.push_back({v.x + x_offset_mm, v.y, v.z});
      for (geometry::GarmentPiece gp : s.ps->garment->pieces) {
        gp.piece += first_piece;
        for (int& vi : gp.vertex_3d) vi += first_vertex;
        ps.garment->pieces.push_back(std::move(gp));
      }
      if (s.ps->garment_is_3d) x_offset_mm += 800;  // garments side by side in the order's garment.obj
      if (ps.finishing.job_name.empty()) {
        ps.finishing = c->ps->finishing;
        ps.finishing.job_name = ps.job.name;
        ps.finishing.edge_widths.clear();
      }
      // Per-edge allowances follow the renamed pieces.
      for (const auto& e : c->ps->finishing.edge_widths) {
        auto copy = e;
        copy.piece += "." + s.stem + "." + std::to_string(c->copy);
        ps.finishing.edge_widths.push_back(copy);
      }
      nlohmann::json fields = nlohmann::json::object();
      for (const auto& [k, v] : c->fields) fields[k] = v;
      nlohmann::json texts = nlohmann::json::array();
      for (const DesignLayerSpec& l : filled)
        if (l.type == "text") texts.push_back(l.text);
      copies.push_back({{"copy", c->copy},
                        {"size", s.spec.size},
                        {"fields", fields},
                        {"texts", texts},
                        {"label", c->job.name},
                        {"pieces", names}});
      size_report["copies"].push_back(c->copy);
      c->ps->renderer.reset();
      if (!first) {
        first = c;
        // Continuity of this size, as its first copy prints (every copy differs only in text).
        if (!s.ps->pattern.stitches.empty()) {
          auto cont = geometry::measure_continuity(s.ps->pattern, *s.ps->garment, c->ps->finishing, *renderer, 150);
          if (!cont)
            return fail(ErrorCode::kPipeline, "order size '" + s.spec.size + "': continuity: " + cont.error().message);
          size_report["seams"] = stats_json(cont->seams);
          size_report["seams"]["dpi"] = 150;
          size_report["seams"]["count"] = cont->seam_list.size();
          size_report["allowance"] = stats_json(cont->allowance);
        }
      }
      // The copy's pattern and garment were only the renderer's input: the order's merged ones remain.
      c->ps->garment.reset();
      c->ps->pattern = {};
      run.copies.push_back(c);
    }
    sizes.push_back(std::move(size_report));
  }
  ps.renderer = std::make_unique<OrderRenderer>(std::move(pieces));
  // Each copy's design state already names its layers; the order's is the base design's.
  ps.report["design"] = run.copies.front()->report["design"];
  ps.report["design"]["placement"] = order.placement;
  ps.report["design"]["base_size"] = order.base_size;
  ps.report["sizes"] = std::move(sizes);
  ps.report["copies"] = std::move(copies);
  ps.report["order"] = {{"placement", order.placement},   {"marker_budget", order.marker_budget},
                        {"base_size", order.base_size},   {"garments", total},
                        {"size_count", run.sizes.size()}, {"piece_count", ps.pattern.pieces.size()}};
  ps.report["piece_count"] = ps.pattern.pieces.size();
  return {};
}

void finish_order_report(nlohmann::json& report) {
  if (!report.contains("order") || !report["order"].is_object()) return;
  nlohmann::json& o = report["order"];
  if (report.contains("marker") && report["marker"].is_object()) {
    const nlohmann::json& m = report["marker"];
    o["fabric_length_mm"] = m.value("length_mm", 0.0);
    o["fabric_width_mm"] = m.value("fabric_width_mm", 0.0);
    o["utilisation"] = m.value("utilisation", 0.0);
    o["markers"] = m.contains("markers") ? m["markers"].size() : 0;
  }
  if (report.contains("ink")) o["ink"] = report["ink"];
}

}  // namespace tp::host::internal
