// host/job/manifest.cpp: job.json schema: every field typed, ranged, unit-checked and located.
#include "host/job/manifest.h"

#include "host/job/calibration_set.h"

#include <fstream>
#include <sstream>

#include "geometry/sewing/cloth_material.h"
#include "host/job/design_limits.h"
#include "host/job/internal/field_reader.h"
#include "host/job/internal/order_manifest.h"

namespace tp::host {

namespace fs = std::filesystem;
using internal::FieldReader;
using internal::Problems;

namespace internal {

// Resolves an asset field into `out` (reporting unsafe or missing files as problems).
void read_asset(FieldReader& r, const std::string& key, bool required, const JobPackage* pkg,
                std::optional<fs::path>& out) {
  auto rel = r.string(key, required);
  if (!rel) return;
  if (!pkg) {
    out = fs::path(*rel);
    return;
  }
  auto resolved = pkg->resolve_asset(*rel, r.pointer_of(key));
  if (!resolved) {
    // resolve_asset already names job.json and the pointer.
    const std::string& m = resolved.error().message;
    const std::string prefix = r.problems().file() + ": ";
    r.problems().add(r.pointer_of(key), m.rfind(prefix, 0) == 0 ? m.substr(m.find(": ", prefix.size()) + 2) : m);
    return;
  }
  out = *resolved;
}

}  // namespace internal

using internal::read_asset;

namespace {

constexpr double kMaxLengthMm = 100000.0;  // 100 m: longer than any marker or garment
// Nesting budgets in separator iterations: the default of `marker.reproducible`, and the most a
// job may ask for.
constexpr int kDefaultNestIterations = 20000;
constexpr int kMaxNestIterations = 10'000'000;

// garment.material: a preset name, or {"preset": name, <field>: value, ...} overriding its values.
void read_material(FieldReader& g, GarmentMaterialSpec& spec) {
  const nlohmann::json* raw = g.raw("material");
  if (!raw) return;
  const std::vector<std::string> presets = geometry::cloth_material_names();
  if (raw->is_string()) {
    if (auto v = g.choice("material", false, presets)) spec.preset = *v;
    return;
  }
  auto m = g.object("material", false);
  if (!m) return;
  m->reject_unknown({"preset", "density_g_m2", "stretch_limit", "bending_rigidity_uN_m", "friction"});
  if (auto v = m->choice("preset", false, presets)) spec.preset = *v;
  spec.density_g_m2 = m->number("density_g_m2", false, 1, 2000);
  spec.stretch_limit = m->number("stretch_limit", false, 0.001, 0.5);
  spec.bending_rigidity_uN_m = m->number("bending_rigidity_uN_m", false, 0, 10000);
  spec.friction = m->number("friction", false, 0, 2);
}

void read_garment(FieldReader g, const JobPackage* pkg, GarmentSpec& spec) {
  g.reject_unknown({"pattern", "pattern_format", "garment_mesh", "sample", "size", "body", "stitches", "mesh_edge",
                    "suggest_min_score", "stitches_file", "checks", "material", "drape", "correspondence", "sewing"});
  read_asset(g, "pattern", false, pkg, spec.pattern);
  if (auto v = g.choice("pattern_format", false, {"auto", "native", "garmentcode", "freesewing-svg", "dxf-aama"}))
    spec.pattern_format = *v;
  read_asset(g, "garment_mesh", false, pkg, spec.garment_mesh);
  if (auto v = g.string("sample", false)) spec.sample = *v;
  if (auto v = g.string("size", false)) spec.size = *v;
  if (auto v = g.choice("stitches", false, {"pattern", "suggest"})) spec.stitches = *v;
  if (auto v = g.length_mm("mesh_edge", false, 2, 200)) spec.mesh_edge_mm = *v;
  if (auto v = g.number("suggest_min_score", false, 0, 1)) spec.suggest_min_score = *v;
  read_asset(g, "stitches_file", false, pkg, spec.stitches_file);
  if (auto c = g.object("checks", false)) {
    c->reject_unknown({"stitch_gap", "self_intersections", "inside_body", "body_crossings", "off_body"});
    if (auto v = c->length_mm("stitch_gap", false, 0, 1000)) spec.checks.max_stitch_gap_mm = *v;
    if (auto v = c->number("self_intersections", false, 0, 1)) spec.checks.max_self_intersections = *v;
    if (auto v = c->number("inside_body", false, 0, 1)) spec.checks.max_inside_body = *v;
    if (auto v = c->number("body_crossings", false, 0, 1)) spec.checks.max_body_crossings = *v;
    if (auto v = c->number("off_body", false, 0, 1)) spec.checks.max_off_body = *v;
  }
  read_material(g, spec.material);
  if (auto v = g.boolean("drape", false)) spec.drape = *v;
  if (auto v = g.choice("sewing", false, {"auto", "arap", "xpbd"})) spec.sewing = *v;
  if (auto v = g.choice("correspondence", false, {"sewn", "draped"})) spec.correspondence = *v;
  if (spec.correspondence == "draped" && !spec.drape)
    g.problems().add(g.pointer_of("correspondence"), "\"draped\" needs \"drape\": true");
  int sources = (spec.pattern ? 1 : 0) + (spec.garment_mesh ? 1 : 0) + (spec.sample.empty() ? 0 : 1);
  if (sources == 0 && !g.problems().items().size())
    g.problems().add(g.pointer(), "one of \"pattern\", \"garment_mesh\" or \"sample\" is required");
  else if (sources > 1)
    g.problems().add(g.pointer(), "give only one of \"pattern\", \"garment_mesh\" or \"sample\"");

  if (auto body = g.object("body", false)) {
    body->reject_unknown({"dress_form", "mesh", "units"});
    if (auto df = body->object("dress_form", false)) {
      spec.body_kind = "dress_form";
      const nlohmann::json* raw = body->raw("dress_form");
      for (auto it = raw->begin(); it != raw->end(); ++it) {
        if (auto mm = df->length_mm(it.key(), true, 1, 3000)) spec.dress_form_mm.emplace_back(it.key(), *mm);
      }
    }
    if (body->has("mesh")) {
      spec.body_kind = "mesh";
      read_asset(*body, "mesh", true, pkg, spec.body_mesh);
      auto units = body->choice("units", true, {"mm", "cm", "m", "in"});
      if (units) spec.body_mesh_scale_to_mm = *units == "mm" ? 1 : *units == "cm" ? 10 : *units == "m" ? 1000 : 25.4;
    } else if (body->has("units")) {
      body->problems().add(body->pointer_of("units"), "\"units\" belongs with \"mesh\"");
    }
    if (body->has("dress_form") && body->has("mesh"))
      body->problems().add(body->pointer(), "give either \"dress_form\" or \"mesh\", not both");
  }
}

// An RGBA colour: four numbers 0..255.
void read_colour(FieldReader& l, const std::string& key, std::array<int, 4>& out) {
  if (auto v = l.vector<4>(key, false, false)) {
    for (int i = 0; i < 4; ++i) {
      if ((*v)[i] < 0 || (*v)[i] > 255)
        l.problems().add(l.pointer_of(key) + "/" + std::to_string(i), "channel outside 0..255");
      out[i] = static_cast<int>((*v)[i]);
    }
  }
}

void read_layer(FieldReader l, const JobPackage* pkg, DesignLayerSpec& s) {
  auto type = l.choice("type", true, {"planar", "cylindrical", "stroke", "texture", "text"});
  if (!type) return;
  s.type = *type;
  if (auto v = l.string("name", false)) s.name = *v;
  if (auto v = l.number("opacity", false, 0, 1)) s.opacity = *v;
  std::set<std::string> known{"type", "name", "opacity"};
  auto image_source = [&]() {
    known.insert({"image", "procedural"});
    if (auto p = l.object("procedural", false)) {
      p->reject_unknown({"kind", "seed", "size_px", "count", "vertical"});
      if (auto k = p->choice("kind", true, {"marbling", "stripes", "motif"})) s.procedural = *k;
      if (auto v = p->integer("count", false, 1, 1000)) s.procedural_count = *v;
      if (auto v = p->boolean("vertical", false)) s.procedural_vertical = *v;
      if (auto v = p->integer("seed", false, 0, 1 << 30)) s.procedural_seed = *v;
      if (auto v = p->integer("size_px", false, 16, 16384)) s.procedural_size_px = *v;
    }
    read_asset(l, "image", false, pkg, s.image);
    if (!s.image && s.procedural.empty() && !l.has("image") && !l.has("procedural"))
      l.problems().add(l.pointer(), "a " + s.type + " layer needs \"image\" or \"procedural\"");
    if (l.has("image") && l.has("procedural"))
      l.problems().add(l.pointer(), "give either \"image\" or \"procedural\", not both");
  };
  if (s.type == "planar") {
    image_source();
    known.insert({"centre", "normal", "up", "width", "height", "repeat"});
    if (auto v = l.vector<3>("centre", true, true)) s.centre_mm = *v;
    if (auto v = l.vector<3>("normal", false, false)) s.normal = *v;
    if (auto v = l.vector<3>("up", false, false)) s.up = *v;
    if (auto v = l.length_mm("width", true, 1, kMaxLengthMm)) s.width_mm = *v;
    if (auto v = l.length_mm("height", false, 1, kMaxLengthMm)) s.height_mm = *v;
    if (auto v = l.boolean("repeat", false)) s.repeat = *v;
  } else if (s.type == "cylindrical") {
    image_source();
    known.insert({"axis_origin", "axis_direction", "tile_width", "tile_height", "rotation_deg", "offset", "repeat"});
    if (auto v = l.vector<3>("axis_origin", false, true)) s.axis_origin_mm = *v;
    if (auto v = l.vector<3>("axis_direction", false, false)) s.axis_direction = *v;
    if (auto v = l.length_mm("tile_width", false, 1, kMaxLengthMm)) s.tile_width_mm = *v;
    if (auto v = l.length_mm("tile_height", false, 1, kMaxLengthMm)) s.tile_height_mm = *v;
    if (auto v = l.number("rotation_deg", false, -360, 360)) s.rotation_deg = *v;
    if (auto v = l.vector<2>("offset", false, true)) s.offset_mm = *v;
    s.repeat = true;
    if (auto v = l.boolean("repeat", false)) s.repeat = *v;
  } else if (s.type == "stroke") {
    known.insert({"points", "radius", "colour", "hardness"});
    if (auto v = l.length_mm("radius", true, 0.1, 1000)) s.radius_mm = *v;
    if (auto v = l.number("hardness", false, 0, 1)) s.hardness = *v;
    read_colour(l, "colour", s.colour_rgba);
    if (auto pts = l.vector_list<3>("points", true, true, 1)) s.points_mm = *pts;
  } else if (s.type == "text") {
    // docs/orders.md: a line of text placed like a planar layer, "{field}" filled per copy.
    known.insert({"text", "font", "size", "colour", "outline", "outline_colour", "centre", "normal", "up"});
    if (auto v = l.string("text", true)) {
      if (v->empty() || v->size() > 200) l.problems().add(l.pointer_of("text"), "text must be 1-200 characters");
      s.text = *v;
    }
    read_asset(l, "font", false, pkg, s.font);
    if (auto v = l.length_mm("size", true, 1, 2000)) s.text_size_mm = *v;
    if (auto v = l.length_mm("outline", false, 0, 200)) s.outline_mm = *v;
    read_colour(l, "colour", s.colour_rgba);
    read_colour(l, "outline_colour", s.outline_rgba);
    if (auto v = l.vector<3>("centre", true, true)) s.centre_mm = *v;
    if (auto v = l.vector<3>("normal", false, false)) s.normal = *v;
    if (auto v = l.vector<3>("up", false, false)) s.up = *v;
  } else if (s.type == "texture") {
    known.insert({"mesh", "image", "units", "max_distance"});
    read_asset(l, "mesh", true, pkg, s.mesh);
    read_asset(l, "image", true, pkg, s.image);
    if (auto units = l.choice("units", false, {"mm", "cm", "m", "in"}))
      s.mesh_scale_to_mm = *units == "mm" ? 1 : *units == "cm" ? 10 : *units == "m" ? 1000 : 25.4;
    if (auto v = l.length_mm("max_distance", false, 0.1, 1000)) s.max_distance_mm = *v;
  }
  l.reject_unknown(known);
}

void read_finishing(FieldReader f, FinishingSpec& s) {
  f.reject_unknown({"seam_allowance", "hem_allowance", "edges", "corner_style", "notches", "labels", "cutter_roll_axis"});
  if (auto v = f.choice("cutter_roll_axis", false, {"x", "y"})) s.cutter_roll_axis = *v;
  if (auto v = f.length_mm("seam_allowance", false, 0, 100)) s.seam_allowance_mm = *v;
  if (auto v = f.length_mm("hem_allowance", false, 0, 200)) s.hem_allowance_mm = *v;
  if (auto v = f.choice("corner_style", false, {"mitre", "square", "mirror"})) s.corner_style = *v;
  if (auto v = f.boolean("notches", false)) s.notches = *v;
  if (auto v = f.choice("labels", false, {"inside", "separate", "none"})) s.labels = *v;
  for (auto& e : f.objects("edges", false)) {
    e.reject_unknown({"piece", "edge", "allowance"});
    auto piece = e.string("piece", true);
    auto edge = e.string("edge", true);
    auto mm = e.length_mm("allowance", true, 0, 200);
    if (piece && edge && mm) s.edges.push_back({*piece, *edge, *mm});
  }
}

void read_marker(FieldReader m, MarkerSpec& s) {
  m.reject_unknown({"fabric_width", "gap", "edge_margin", "rotations", "mirror", "time_limit_s", "budget",
                    "reproducible", "seed", "max_length", "defects"});
  if (auto v = m.length_mm("fabric_width", true, 100, 10000)) s.fabric_width_mm = *v;
  if (auto v = m.length_mm("gap", false, 0, 100)) s.gap_mm = *v;
  if (auto v = m.length_mm("edge_margin", false, 0, 500)) s.edge_margin_mm = *v;
  if (auto v = m.choice("rotations", false, {"grain", "90", "free", "fixed"})) s.rotations = *v;
  if (auto v = m.boolean("mirror", false)) s.mirror = *v;
  if (auto v = m.number("time_limit_s", false, 0, 3600)) s.time_limit_s = *v;
  if (auto b = m.object("budget", false)) {
    b->reject_unknown({"seconds", "iterations"});
    if (b->has("seconds") == b->has("iterations"))
      m.problems().add(m.pointer_of("budget"), "give either \"seconds\" or \"iterations\"");
    if (auto v = b->number("seconds", false, 0, 3600)) s.time_limit_s = *v;
    if (auto v = b->integer("iterations", false, 1, kMaxNestIterations)) s.iterations = *v;
  }
  // Reproducible unless the job gives seconds or says `reproducible: false`: the same job then
  // nests the same marker on any machine and under any load.
  const auto reproducible = m.boolean("reproducible", false);
  const bool gives_seconds = m.has("time_limit_s") || (m.has("budget") && s.iterations == 0);
  if (reproducible && *reproducible && gives_seconds)
    m.problems().add(m.pointer_of("reproducible"),
                     "a reproducible marker has an iteration budget, not seconds: "
                     "give budget {\"iterations\": N} or no time limit");
  if (s.iterations == 0 && !gives_seconds && reproducible.value_or(true)) s.iterations = kDefaultNestIterations;
  if (auto v = m.integer("seed", false, 0, 1 << 30)) s.seed = *v;
  if (auto v = m.length_mm("max_length", false, 100, kMaxLengthMm)) s.max_length_mm = *v;
  for (auto& d : m.objects("defects", false)) {
    d.reject_unknown({"x", "y", "width", "length"});
    auto x = d.length_mm("x", true, 0, 10000), y = d.length_mm("y", true, 0, kMaxLengthMm);
    auto w = d.length_mm("width", true, 0.1, 10000), l = d.length_mm("length", true, 0.1, kMaxLengthMm);
    if (x && y && w && l) s.defects.push_back({*x, *y, *w, *l});
  }
}

void read_print(FieldReader p, const JobPackage* pkg, PrintSpec& s) {
  p.reject_unknown({"printer", "printer_model", "dpi", "passes", "bidirectional", "screen", "levels", "icc_profile",
                    "ink_limit_pct", "separations_tiff", "preview_dpi", "transfer", "calibration", "device_inks"});
  if (auto v = p.choice("transfer", false, {"direct", "sublimation"})) s.transfer = *v;
  // A job prints on the simulator or a real printer; "none" is a run's override only (printctl, printd).
  const std::vector<std::string> job_printers{std::string(to_string(PrinterChoice::kSim)),
                                              std::string(to_string(PrinterChoice::kUsb))};
  if (auto v = p.choice("printer", false, job_printers)) s.printer = parse_printer_choice(*v).value_or(s.printer);
  read_asset(p, "printer_model", false, pkg, s.printer_model);
  if (auto v = p.integer("dpi", false, 25, 2400)) s.dpi = *v;
  if (auto v = p.integer("passes", false, 1, 8)) {
    if (*v != 1 && *v != 2 && *v != 4 && *v != 8) p.problems().add(p.pointer_of("passes"), "passes must be 1, 2, 4 or 8");
    s.passes = *v;
  }
  if (auto v = p.boolean("bidirectional", false)) s.bidirectional = *v;
  if (auto v = p.choice("screen", false, {"blue-noise", "error-diffusion"})) s.screen = *v;
  if (auto v = p.integer("levels", false, 2, 4)) {
    if (*v == 3) p.problems().add(p.pointer_of("levels"), "levels must be 2 (bi-level) or 4 (none/small/medium/large)");
    s.levels = *v;
  }
  read_asset(p, "icc_profile", false, pkg, s.icc_profile);
  read_asset(p, "calibration", false, pkg, s.calibration);
  if (s.calibration && pkg) {
    if (auto set = load_calibration_set(*s.calibration)) {
      if (!set->profile.empty()) s.calibration_profile = set->profile;
      s.calibration_set = std::move(*set);
    } else {
      p.problems().add(p.pointer_of("calibration"), set.error().message);
    }
  }
  if (const nlohmann::json* d = p.raw("device_inks")) {
    bool ok = d->is_array() && !d->empty() && d->size() <= 3;
    for (const auto& v : ok ? *d : nlohmann::json::array()) {
      ok = ok && v.is_string() && !v.get<std::string>().empty();
      if (ok) s.device_inks.push_back(v.get<std::string>());
    }
    if (!ok) p.problems().add(p.pointer_of("device_inks"), "expected 1 to 3 ink names (the inks R, G and B drive)");
    if (ok && s.calibration_profile)
      p.problems().add(p.pointer_of("device_inks"), "prints device values: the calibration's profile cannot apply");
  }
  if (auto v = p.number("ink_limit_pct", false, 100, 400)) s.ink_limit_pct = *v;
  if (auto v = p.boolean("separations_tiff", false)) s.separations_tiff = *v;
  if (auto v = p.integer("preview_dpi", false, 5, 300)) s.preview_dpi = *v;
}

}  // namespace

Result<Job> parse_job(const std::string& text, const JobPackage* pkg) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    return fail(ErrorCode::kValidation, std::string("job.json: not valid JSON: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    // A number too large for a double (out_of_range.406) and the like: still the file's fault.
    return fail(ErrorCode::kValidation, std::string("job.json: not valid JSON: ") + e.what());
  }
  Problems problems("job.json");
  if (!doc.is_object()) return fail(ErrorCode::kValidation, "job.json: /: expected a JSON object");
  FieldReader top(doc, "", problems);
  top.reject_unknown({"format", "name", "garment", "design", "finishing", "marker", "print", "order"});

  Job job;
  if (auto fmt = top.string("format", true); fmt && *fmt != kJobFormat)
    problems.add("/format", "unsupported format \"" + *fmt + "\" (this host reads \"" + kJobFormat + "\")");
  if (auto name = top.string("name", true)) {
    bool ok = !name->empty() && name->size() <= 100;
    for (char c : *name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.');
    if (!ok || (*name)[0] == '.')
      problems.add("/name", "job name \"" + *name + "\" must be 1-100 letters, digits, '-', '_' or '.' (not leading)");
    else
      job.name = *name;
  }
  if (auto g = top.object("garment", true)) read_garment(*g, pkg, job.garment);
  if (auto d = top.object("design", false)) {
    d->reject_unknown({"layers"});
    for (auto& l : d->objects("layers", true)) {
      DesignLayerSpec s;
      read_layer(l, pkg, s);
      job.design.push_back(std::move(s));
    }
  }
  if (auto f = top.object("finishing", false)) read_finishing(*f, job.finishing);
  if (auto m = top.object("marker", true)) read_marker(*m, job.marker);
  if (auto p = top.object("print", false)) read_print(*p, pkg, job.print);
  if (auto o = top.object("order", false)) internal::read_order(*o, pkg, job);
  internal::check_text_layers(job, problems);

  if (!problems.empty()) {
    bool unsafe = false;
    std::string msg;
    for (const auto& item : problems.items()) {
      msg += (msg.empty() ? "" : "\n") + item;
      unsafe = unsafe || item.find("leaves the package") != std::string::npos ||
               item.find("absolute path") != std::string::npos;
    }
    return fail(unsafe ? ErrorCode::kUnsafePath : ErrorCode::kValidation, msg);
  }
  if (pkg) {
    job.package_root = pkg->root();
    job.manifest = pkg->root() / "job.json";
  }
  return job;
}

Result<Job> load_job(const JobPackage& package) {
  const fs::path path = package.root() / "job.json";
  const std::uint64_t cap = package.limits().max_manifest_bytes;
  // The size is checked before a byte is read, and the read itself is capped (the file may grow).
  std::error_code ec;
  const auto bytes = fs::file_size(path, ec);
  if (ec) return fail(ErrorCode::kIo, path.string() + ": " + ec.message());
  const std::string too_big = "job.json: " + std::to_string(bytes) + " bytes, over the limit of " + std::to_string(cap) +
                              " (max_manifest_bytes; raise it with --limit max_manifest_bytes=N)";
  if (bytes > cap) return fail(ErrorCode::kValidation, too_big);
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, path.string() + ": cannot read");
  std::string text(static_cast<size_t>(bytes) + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > cap) return fail(ErrorCode::kValidation, too_big);
  auto job = parse_job(text, &package);
  if (!job) return job;
  if (auto st = check_design_limits(*job, package.limits()); !st) return std::unexpected(st.error());
  return job;
}

}  // namespace tp::host
