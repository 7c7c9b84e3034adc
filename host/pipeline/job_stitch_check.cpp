// host/pipeline/job_stitch_check.cpp: the pattern read and its stitches counted as the pattern stage will.
#include "host/pipeline/job_stitch_check.h"

#include <cstdio>

#include "geometry/pattern/import/load_pattern.h"
#include "geometry/pattern/stitches_json.h"
#include "geometry/pattern/suggest_stitches.h"

namespace tp::host {

std::string no_stitches_message(const GarmentSpec& g, const std::string& pattern_name) {
  char score[32];
  std::snprintf(score, sizeof score, "%.2f", g.suggest_min_score);
  return "pattern '" + pattern_name + "': no stitches to sew it on the body with (the pattern has none" +
         (g.stitches == "suggest"
              ? std::string(" and no suggestion scored ") + score + " or more"
              : std::string("; set /garment/stitches to \"suggest\" or give /garment/stitches_file")) +
         "); a job without a body prints it flat";
}

Status check_job_stitches(const Job& job) {
  const GarmentSpec& g = job.garment;
  if (g.body_kind == "none" || !g.pattern || g.garment_mesh || !g.sample.empty()) return {};
  auto pattern = geometry::load_pattern(*g.pattern, geometry::PatternImportOptions{});
  if (!pattern)
    return fail(Error{ErrorCode::kValidation, pattern.error().what()}.with_context("job.json: /garment/pattern"));
  if (!pattern->stitches.empty()) return {};
  if (g.stitches_file) {
    auto st = geometry::load_stitches_json(*g.stitches_file, *pattern);
    if (!st)
      return fail(Error{ErrorCode::kValidation, st.error().message}.with_context("job.json: /garment/stitches_file"));
    if (!st->empty()) return {};
  }
  if (g.stitches == "suggest") {
    geometry::SuggestOptions opt;
    opt.min_score = g.suggest_min_score;
    for (const auto& s : geometry::suggest_stitches(*pattern, opt))
      if (!s.stitches.empty()) return {};
  }
  return fail(ErrorCode::kValidation, "job.json: /garment: " + no_stitches_message(g, pattern->name));
}

}  // namespace tp::host
