// host/pipeline/stage_design.cpp: the design stage: the job's layers (images read through the
// RIP's colour-managed reader, or generated), its finishing, and the piece renderer over both.
#include <list>
#include <mutex>

#include "geometry/design/make_piece_renderer.h"
#include "geometry/design/text_layer.h"
#include "geometry/design/texture_model.h"
#include "geometry/design/textures.h"
#include "geometry/design/validate_design.h"
#include "host/pipeline/internal/pipeline_state.h"
#include "rip/image/image_io.h"

namespace tp::host::internal {

namespace {

/// Procedural tiles kept for layers asking for the same one again (16 MiB each at 2048 px).
constexpr std::size_t kProceduralKept = 4;

geometry::Vec3 vec3(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
geometry::Rgba8 rgba(const std::array<int, 4>& c) {
  return {static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]), static_cast<std::uint8_t>(c[2]),
          static_cast<std::uint8_t>(c[3])};
}

// A procedural texture, generated once per process for the same parameters: the studio renders
// a design again after every change, and a 2048 px tile takes longer than the rest of a preview.
// Generation is deterministic, so a kept tile is the one that would be made again.
Result<geometry::ImageHandle> procedural_image(const DesignLayerSpec& s, const std::string& where) {
  const std::string key = s.procedural + "/" + std::to_string(s.procedural_seed) + "/" +
                          std::to_string(s.procedural_size_px) + "/" + std::to_string(s.procedural_count) + "/" +
                          std::to_string(s.procedural_vertical);
  static std::mutex mu;
  static std::list<std::pair<std::string, geometry::ImageHandle>> kept;  // most recent first
  {
    std::lock_guard lock(mu);
    for (auto it = kept.begin(); it != kept.end(); ++it)
      if (it->first == key) {
        kept.splice(kept.begin(), kept, it);
        return kept.front().second;
      }
  }
  geometry::ImageRgba8 img;
  if (s.procedural == "marbling") {
    geometry::MarblingOptions o;
    o.width_px = o.height_px = s.procedural_size_px;
    o.seed = static_cast<std::uint32_t>(s.procedural_seed);
    img = geometry::marbling(o);
  } else if (s.procedural == "stripes") {
    img = geometry::stripes(s.procedural_size_px, s.procedural_size_px, s.procedural_count, s.procedural_vertical,
                            {{20, 40, 110, 255}, {245, 240, 225, 255}});
  } else if (s.procedural == "motif") {
    img = geometry::placement_motif(s.procedural_size_px);
  } else {
    return fail(ErrorCode::kValidation, where + ": no image source");
  }
  img.source = "procedural:" + s.procedural;
  geometry::ImageHandle handle = std::make_shared<const geometry::ImageRgba8>(std::move(img));
  std::lock_guard lock(mu);
  kept.emplace_front(key, handle);
  if (kept.size() > kProceduralKept) kept.pop_back();
  return handle;
}

// A layer's image: a file from the package or a procedural texture.
Result<geometry::ImageHandle> layer_image(const DesignLayerSpec& s, size_t index) {
  const std::string where = "job.json: /design/layers/" + std::to_string(index);
  if (s.image) {
    auto img = rip::read_image(*s.image);
    if (!img) return fail(ErrorCode::kValidation, where + "/image: " + img.error().message);
    return std::make_shared<const geometry::ImageRgba8>(std::move(*img));
  }
  return procedural_image(s, where);
}

Result<geometry::Design> build_design(const Job& job) {
  geometry::Design d;
  for (size_t i = 0; i < job.design.size(); ++i) {
    const DesignLayerSpec& s = job.design[i];
    geometry::DesignLayer layer;
    layer.name = s.name.empty() ? s.type + "-" + std::to_string(i) : s.name;
    layer.opacity = s.opacity;
    if (s.type == "cylindrical" || s.type == "planar") {
      auto img = layer_image(s, i);
      if (!img) return fail(img.error());
      if (s.type == "cylindrical") {
        geometry::CylindricalProjection c;
        c.image = *img;
        if (s.axis_origin_mm) c.axis_origin_mm = vec3(*s.axis_origin_mm);
        if (s.axis_direction) c.axis_direction = geometry::normalized(vec3(*s.axis_direction));
        c.tile_width_mm = s.tile_width_mm;
        c.tile_height_mm = s.tile_height_mm;
        c.rotation_deg = s.rotation_deg;
        c.offset_mm = {s.offset_mm[0], s.offset_mm[1]};
        c.repeat = s.repeat;
        layer.content = std::move(c);
      } else {
        geometry::PlanarProjection p;
        p.image = *img;
        p.centre_mm = vec3(s.centre_mm);
        p.normal = geometry::normalized(vec3(s.normal));
        p.up = geometry::normalized(vec3(s.up));
        p.width_mm = s.width_mm;
        p.height_mm = s.height_mm;
        p.repeat = s.repeat;
        layer.content = std::move(p);
      }
    } else if (s.type == "stroke") {
      geometry::BrushStroke b;
      for (const auto& p : s.points_mm) b.points_mm.push_back(vec3(p));
      b.radius_mm = s.radius_mm;
      b.colour = {static_cast<std::uint8_t>(s.colour_rgba[0]), static_cast<std::uint8_t>(s.colour_rgba[1]),
                  static_cast<std::uint8_t>(s.colour_rgba[2]), static_cast<std::uint8_t>(s.colour_rgba[3])};
      b.hardness = s.hardness;
      layer.content = std::move(b);
    } else if (s.type == "text") {
      // A line of text (an order copy's fields already filled in) rendered and placed like a planar layer.
      geometry::TextStyle ts;
      if (s.font) ts.font_file = *s.font;
      ts.cap_height_mm = s.text_size_mm;
      ts.colour = rgba(s.colour_rgba);
      ts.outline_mm = s.outline_mm;
      ts.outline_colour = rgba(s.outline_rgba);
      auto t = geometry::render_text_image(s.text, ts);
      if (!t)
        return fail(ErrorCode::kValidation,
                    "job.json: /design/layers/" + std::to_string(i) + "/text: " + t.error().message);
      geometry::PlanarProjection p;
      p.image = std::make_shared<const geometry::ImageRgba8>(std::move(t->image));
      p.normal = geometry::normalized(vec3(s.normal));
      p.up = geometry::normalized(vec3(s.up));
      // The image is cropped to the ink: its centre sits off the line's centre in the image
      // plane (right = -normal x up, as the planar projection sees it).
      const geometry::Vec3 up = geometry::normalized(p.up - p.normal * geometry::dot(p.up, p.normal));
      const geometry::Vec3 right = geometry::cross(-p.normal, up);
      p.centre_mm = vec3(s.centre_mm) + right * t->offset_right_mm + up * t->offset_up_mm;
      p.width_mm = t->width_mm;
      p.height_mm = t->height_mm;
      layer.content = std::move(p);
    } else if (s.type == "texture" && s.mesh) {
      const std::string where = "job.json: /design/layers/" + std::to_string(i);
      auto model = geometry::load_texture_model(*s.mesh, s.mesh_scale_to_mm);
      if (!model) return fail(ErrorCode::kValidation, where + "/mesh: " + model.error().message);
      auto img = layer_image(s, i);
      if (!img) return fail(img.error());
      model->image = *img;
      model->max_distance_mm = s.max_distance_mm;
      layer.content = std::move(*model);
    } else {
      return fail(ErrorCode::kValidation, "job.json: /design/layers/" + std::to_string(i) + ": unknown layer type '" +
                                              s.type + "'");
    }
    d.layers.push_back(std::move(layer));
  }
  return d;
}

geometry::Finishing build_finishing(const Job& job) {
  const FinishingSpec& f = job.finishing;
  geometry::Finishing out;
  out.seam_allowance_mm = f.seam_allowance_mm;
  out.hem_allowance_mm = f.hem_allowance_mm;
  out.edge_allowance_mm = f.seam_allowance_mm;
  for (const auto& e : f.edges) out.edge_widths.push_back({e.piece, e.edge, e.allowance_mm});
  if (f.corner_style == "square") out.seam_corner = geometry::CornerStyle::kSquare;
  else if (f.corner_style == "mirror") out.seam_corner = geometry::CornerStyle::kReflectIncoming;
  else out.seam_corner = geometry::CornerStyle::kMitre;
  out.notch_stitch_ends = f.notches;
  out.marks = f.labels == "inside"     ? geometry::MarkMode::kPrinted
              : f.labels == "separate" ? geometry::MarkMode::kMarkerLayer
                                       : geometry::MarkMode::kNone;
  out.job_name = job.name;
  return out;
}

}  // namespace

Status stage_design(PipelineState& ps) {
  auto design = build_design(ps.job);
  if (!design) return fail(design.error());
  ps.design = std::move(*design);
  ps.finishing = build_finishing(ps.job);
  if (!ps.renderer_base) {
    if (auto st = geometry::validate_design(ps.design); !st) return fail(ErrorCode::kPipeline, st.error().message);
    auto base = geometry::prepare_piece_renderer(ps.pattern, *ps.garment, ps.finishing, ps.render_options, &ps.cancel);
    if (!base) {
      auto code = base.error().code == geometry::ErrorCode::kCancelled ? ErrorCode::kCancelled : ErrorCode::kPipeline;
      return fail(code, base.error().message);
    }
    ps.renderer_base = std::move(*base);
  }
  auto renderer = ps.overlay_margin_mm > 0
                      ? geometry::make_overlay_renderer(ps.renderer_base, ps.design, ps.overlay_margin_mm, &ps.cancel)
                      : geometry::make_piece_renderer(ps.renderer_base, ps.design, &ps.cancel);
  if (!renderer) {
    auto code = renderer.error().code == geometry::ErrorCode::kCancelled ? ErrorCode::kCancelled : ErrorCode::kPipeline;
    return fail(code, renderer.error().message);
  }
  ps.renderer = std::move(*renderer);
  nlohmann::json layers = nlohmann::json::array();
  for (const auto& l : ps.design.layers) layers.push_back(l.name);
  ps.report["design"] = {{"layers", layers},
                         {"seam_allowance_mm", ps.finishing.seam_allowance_mm},
                         {"hem_allowance_mm", ps.finishing.hem_allowance_mm}};
  return {};
}

}  // namespace tp::host::internal
