// host/job/order_manifest.cpp: job.json "order": sizes with quantities (and per-size pattern and
// body for imported patterns), placement, and the copies' fields inline or from a CSV asset.
#include "host/job/internal/order_manifest.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "geometry/samples/sizes.h"
#include "host/job/copy_text.h"

namespace tp::host::internal {

namespace {

constexpr int kMaxGarments = 1000;
// The most a marker budget may grow to with "marker_budget": "per_garment" (job.json's own limits).
constexpr int kMaxIterations = 10'000'000;
constexpr double kMaxSeconds = 3600;

// Splits one CSV line (RFC 4180 quoting, no newlines inside quotes) into fields.
std::vector<std::string> csv_fields(const std::string& line, bool& ok) {
  std::vector<std::string> out(1);
  bool quoted = false;
  ok = true;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        out.back() += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        out.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else if (c != '\r') {
      out.back() += c;
    }
  }
  ok = !quoted;
  return out;
}

// copies_csv: a header row of field names, then one row per copy.
void read_copies_csv(const std::filesystem::path& path, const std::string& pointer, Problems& problems,
                     OrderSpec& spec) {
  const std::string name = path.filename().string();
  std::ifstream in(path);
  if (!in) return problems.add(pointer, name + ": cannot read");
  std::string line;
  std::vector<std::string> header;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line == "\r") continue;
    bool ok = true;
    auto fields = csv_fields(line, ok);
    if (!ok) return problems.add(pointer, name + ": line " + std::to_string(line_no) + ": unterminated quote");
    if (header.empty()) {
      header = fields;
      std::set<std::string> seen;
      for (const auto& h : header)
        if (h.empty() || !seen.insert(h).second)
          return problems.add(pointer, name + ": line 1: empty or repeated column name '" + h + "'");
      continue;
    }
    if (fields.size() != header.size())
      return problems.add(pointer, name + ": line " + std::to_string(line_no) + ": " + std::to_string(fields.size()) +
                                       " fields, the header has " + std::to_string(header.size()));
    CopyFields copy;
    for (size_t k = 0; k < header.size(); ++k) copy.emplace_back(header[k], fields[k]);
    spec.copies.push_back(std::move(copy));
    if (spec.copies.size() > kMaxGarments) return problems.add(pointer, name + ": more than 1000 copies");
  }
  if (header.empty()) problems.add(pointer, name + ": no header row");
}

}  // namespace

void read_order(FieldReader o, const JobPackage* pkg, Job& job) {
  o.reject_unknown({"sizes", "base_size", "placement", "copies", "copies_csv", "marker_budget"});
  OrderSpec spec;
  Problems& problems = o.problems();
  const GarmentSpec& g = job.garment;
  if (g.garment_mesh)
    problems.add(o.pointer(), "an order needs a pattern or a sample garment to grade, not a garment_mesh");
  const bool imported = g.pattern.has_value();
  if (auto v = o.choice("placement", false, {"body", "graded"})) spec.placement = *v;
  if (auto v = o.choice("marker_budget", false, {"order", "per_garment"})) spec.marker_budget = *v;
  std::set<std::string> names;
  auto sizes = o.objects("sizes", true);
  if (o.has("sizes") && sizes.empty()) problems.add(o.pointer_of("sizes"), "an order needs at least one size");
  for (auto& s : sizes) {
    s.reject_unknown({"size", "quantity", "pattern", "body"});
    OrderSizeSpec sz;
    if (auto v = s.string("size", true)) {
      sz.size = *v;
      if (!names.insert(*v).second) problems.add(s.pointer_of("size"), "size '" + *v + "' is listed twice");
      if (!imported)
        if (auto m = geometry::samples::parse_size(*v); !m)
          problems.add(s.pointer_of("size"), "size '" + *v + "': " + m.error().message);
    }
    if (auto v = s.integer("quantity", true, 1, kMaxGarments)) sz.quantity = *v;
    const std::string label = "size '" + sz.size + "'";
    read_asset(s, "pattern", imported, pkg, sz.pattern);
    if (!imported && s.has("pattern"))
      problems.add(s.pointer_of("pattern"),
                   label + ": the job's garment is a sample, drafted per size; no pattern file");
    if (auto body = s.object("body", false)) {
      body->reject_unknown({"dress_form"});
      if (auto df = body->object("dress_form", true)) {
        const nlohmann::json* raw = body->raw("dress_form");
        for (auto it = raw->begin(); it != raw->end(); ++it)
          if (auto mm = df->length_mm(it.key(), true, 1, 3000)) sz.dress_form_mm.emplace_back(it.key(), *mm);
      }
    }
    if (imported && g.body_kind == "dress_form" && sz.dress_form_mm.empty())
      problems.add(s.pointer(), label + ": the job's body is a dress form, so each size needs body.dress_form");
    if (imported && g.body_kind == "mesh")
      problems.add(s.pointer(), label +
                                    ": orders of an imported pattern take a dress form per size, not a body mesh: "
                                    "the design is carried between sizes through the dress forms' landmarks "
                                    "(bust, waist, hip lines and sections), which a body mesh does not give; "
                                    "give garment.body.dress_form and each size's body.dress_form");
    spec.sizes.push_back(std::move(sz));
  }
  spec.base_size = g.size;
  if (auto v = o.string("base_size", false))
    spec.base_size = *v;
  else if (!names.empty() && !names.count(g.size))
    spec.base_size = spec.sizes.front().size;
  if (!names.empty() && !names.count(spec.base_size))
    problems.add(o.has("base_size") ? o.pointer_of("base_size") : o.pointer(),
                 "base size '" + spec.base_size + "' is not one of the order's sizes");
  if (spec.garments() > kMaxGarments) problems.add(o.pointer_of("sizes"), "more than 1000 garments in one order");

  if (o.has("copies") && o.has("copies_csv"))
    problems.add(o.pointer(), "give either \"copies\" or \"copies_csv\", not both");
  // Each copy: an object of field -> string or whole number (non-objects are reported here).
  const auto copy_readers = o.objects("copies", false);
  if (const nlohmann::json* raw = o.raw("copies"); raw && raw->is_array() && copy_readers.size() == raw->size()) {
    for (size_t k = 0; k < raw->size(); ++k) {
      const nlohmann::json& c = (*raw)[k];
      CopyFields copy;
      if (c.is_object())
        for (auto it = c.begin(); it != c.end(); ++it) {
          const std::string ptr =
              o.pointer_of("copies") + "/" + std::to_string(k) + "/" + escape_pointer_token(it.key());
          if (it->is_string())
            copy.emplace_back(it.key(), it->get<std::string>());
          else if (it->is_number_integer())
            copy.emplace_back(it.key(), std::to_string(it->get<std::int64_t>()));
          else
            problems.add(ptr, "a copy's field is a string or a whole number");
        }
      spec.copies.push_back(std::move(copy));
    }
  }
  read_asset(o, "copies_csv", false, pkg, spec.copies_csv);
  if (spec.copies_csv && pkg) read_copies_csv(*spec.copies_csv, o.pointer_of("copies_csv"), problems, spec);
  if (!spec.copies.empty() && static_cast<int>(spec.copies.size()) != spec.garments())
    problems.add(o.pointer_of(spec.copies_csv ? "copies_csv" : "copies"),
                 std::to_string(spec.copies.size()) + " copies for " + std::to_string(spec.garments()) +
                     " garments (the sizes' quantities add up to " + std::to_string(spec.garments()) + ")");
  // "per_garment": the marker's budget is the job's times the garments, as that many single
  // jobs would have had between them (the order's one marker then nests with as much search).
  if (spec.marker_budget == "per_garment" && spec.garments() > 0) {
    const double n = spec.garments();
    if (job.marker.iterations > 0)
      job.marker.iterations =
          static_cast<int>(std::min(job.marker.iterations * n, static_cast<double>(kMaxIterations)));
    else
      job.marker.time_limit_s = std::min(job.marker.time_limit_s * n, kMaxSeconds);
  }
  job.order = std::move(spec);
}

void check_text_layers(const Job& job, Problems& problems) {
  for (size_t i = 0; i < job.design.size(); ++i) {
    const DesignLayerSpec& l = job.design[i];
    if (l.type != "text") continue;
    const std::string ptr = "/design/layers/" + std::to_string(i) + "/text";
    const auto fields = template_fields(l.text);
    if (fields.empty()) continue;
    if (!job.order || job.order->copies.empty()) {
      problems.add(ptr,
                   "'" + l.text + "' takes {" + fields.front() + "} from the order's copies, and the job has none");
      continue;
    }
    for (size_t k = 0; k < job.order->copies.size(); ++k) {
      std::vector<std::string> missing;
      const std::string text = fill_template(l.text, job.order->copies[k], &missing);
      if (!missing.empty())
        problems.add(ptr, "copy " + std::to_string(k + 1) + " has no field '" + missing.front() + "'" +
                              (job.order->copies_csv ? " (" + job.order->copies_csv->filename().string() + ")" : ""));
      else if (text.empty())
        problems.add(ptr, "copy " + std::to_string(k + 1) + ": the text is empty");
    }
  }
}

}  // namespace tp::host::internal
