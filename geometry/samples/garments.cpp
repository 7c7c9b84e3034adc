// geometry/samples/garments.cpp: dispatch to the sample drafts, and sewing them on their dress form.
#include "geometry/samples/garments.h"

#include "geometry/body/dress_form.h"
#include "geometry/samples/internal/draft.h"
#include "geometry/samples/internal/drafts.h"
#include "geometry/samples/sizes.h"

namespace tp::geometry::samples {

const std::vector<std::string>& garment_names() {
  static const std::vector<std::string> names{"simple_top", "blouse", "dress", "skirt8"};
  return names;
}

Result<Pattern> draft_garment(std::string_view name, const BodyMeasurements& m, const std::string& size_label) {
  if (auto s = validate(m); !s) return std::unexpected(s.error().with_context(std::string(name)));
  Result<Pattern> p = fail(ErrorCode::kInvalidArgument,
                           "unknown garment '" + std::string(name) + "' (simple_top, blouse, dress, skirt8)");
  if (name == "skirt8") p = internal::draft_skirt8(m);
  else if (name == "simple_top") p = internal::draft_simple_top(m);
  else if (name == "blouse") p = internal::draft_blouse(m);
  else if (name == "dress") p = internal::draft_dress(m);
  if (p) p->size = size_label;
  return p;
}

Result<std::shared_ptr<const BodySdf>> make_dress_form_sdf(const BodyMeasurements& m) {
  auto mesh = make_dress_form(m);
  if (!mesh) return std::unexpected(mesh.error());
  auto sdf = BodySdf::build(std::move(*mesh));
  if (!sdf) return std::unexpected(sdf.error());
  return std::make_shared<const BodySdf>(std::move(*sdf));
}

Result<SampleGarment> make_garment(std::string_view name, std::string_view size, const SewOptions& options) {
  auto m = parse_size(size);
  if (!m) return std::unexpected(m.error().with_context("size '" + std::string(size) + "'"));
  SampleGarment out;
  out.measurements = *m;
  auto pattern = draft_garment(name, *m, std::string(size));
  if (!pattern) return std::unexpected(pattern.error());
  out.pattern = std::move(*pattern);
  auto body = make_dress_form_sdf(*m);
  if (!body) return std::unexpected(body.error());
  out.body = *body;
  auto g = sew_garment(out.pattern, *out.body, options, &out.stats);
  if (!g) return std::unexpected(g.error());
  out.garment = std::move(*g);
  return out;
}

}  // namespace tp::geometry::samples
