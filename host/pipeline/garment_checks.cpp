// host/pipeline/garment_checks.cpp: fit-check figures, limits and failures, and the stitch list, as JSON.
#include "host/pipeline/garment_checks.h"

#include <algorithm>

namespace tp::host {

geometry::FitLimits fit_limits(const GarmentChecksSpec& spec) {
  geometry::FitLimits l;
  l.max_stitch_gap_mm = spec.max_stitch_gap_mm;
  l.max_self_intersections = spec.max_self_intersections;
  l.max_inside_body = spec.max_inside_body;
  l.max_body_crossings = spec.max_body_crossings;
  l.max_off_body = spec.max_off_body;
  return l;
}

nlohmann::json checks_json(const geometry::Pattern& pattern, const geometry::FitReport& r, const geometry::FitLimits& limits,
                           const std::string& preview_prefix) {
  nlohmann::json failures = nlohmann::json::array();
  for (const auto& f : r.failures)
    failures.push_back({{"check", f.check}, {"message", f.message}, {"preview", preview_prefix + f.view + ".png"}});
  nlohmann::json unsewn = nlohmann::json::array();
  for (int p : r.unsewn_pieces) unsewn.push_back(pattern.pieces[static_cast<size_t>(p)].name);
  return {{"pass", r.pass},
          {"unsewn_pieces", unsewn},
          {"stitches", r.stitches},
          {"stitch_gap_max_mm", r.stitch_gap_max_mm},
          {"stitch_gap_p95_mm", r.stitch_gap_p95_mm},
          {"worst_stitch", r.worst_stitch},
          {"self_intersections", r.self_intersections},
          {"triangles", r.triangles},
          {"inside_body", r.inside_body},
          {"body_crossings", r.body_crossings},
          {"vertices", r.vertices},
          {"body_distance_p50_mm", r.body_distance_p50_mm},
          {"body_distance_p95_mm", r.body_distance_p95_mm},
          {"off_body", r.off_body},
          {"limits",
           {{"stitch_gap_mm", limits.max_stitch_gap_mm},
            {"self_intersections", limits.max_self_intersections},
            {"inside_body", limits.max_inside_body},
            {"body_crossings", limits.max_body_crossings},
            {"off_body", limits.max_off_body},
            {"off_body_distance_mm", limits.off_body_distance_mm}}},
          {"failures", failures}};
}

nlohmann::json stitches_json(const geometry::Pattern& pattern, const std::vector<nlohmann::json>& sources,
                             const std::vector<std::vector<double>>& gaps_mm) {
  auto side = [&](const geometry::EdgeSpan& s) {
    const geometry::Piece& p = pattern.pieces[static_cast<size_t>(s.piece)];
    auto range = geometry::span_range_mm(pattern, s);
    return nlohmann::json{{"piece", p.name}, {"edge", p.edges[static_cast<size_t>(s.edge)].name},
                          {"from_mm", range[0]}, {"to_mm", range[1]}};
  };
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < pattern.stitches.size(); ++i) {
    const geometry::Stitch& st = pattern.stitches[i];
    nlohmann::json j = i < sources.size() ? sources[i] : nlohmann::json{{"source", "pattern"}};
    j["a"] = side(st.a);
    j["b"] = side(st.b);
    if (st.same_direction) j["same_direction"] = true;
    if (i < gaps_mm.size() && !gaps_mm[i].empty())
      j["gap_max_mm"] = *std::max_element(gaps_mm[i].begin(), gaps_mm[i].end());
    out.push_back(std::move(j));
  }
  return out;
}

std::string checks_failure_message(const geometry::FitReport& r, const std::string& preview_prefix) {
  std::string msg = "garment checks failed: ";
  for (size_t i = 0; i < r.failures.size(); ++i)
    msg += (i ? "; " : "") + r.failures[i].message + " (look at " + preview_prefix + r.failures[i].view + ".png)";
  return msg;
}

}  // namespace tp::host
