// geometry/pattern/stitches_json.cpp: writing suggested stitches as a stitches file and reading one back.
#include "geometry/pattern/stitches_json.h"

#include <nlohmann/json.hpp>

#include <map>

#include "geometry/pattern/internal/json_fields.h"
#include "geometry/pattern/internal/pattern_json_stitches.h"
#include "geometry/pattern/internal/read_file.h"
#include "geometry/pattern/internal/try.h"

namespace tp::geometry {
namespace {

using ojson = nlohmann::ordered_json;

ojson side_json(const Pattern& pattern, const EdgeSpan& s) {
  const Piece& p = pattern.pieces[static_cast<size_t>(s.piece)];
  ojson j{{"piece", p.name}, {"edge", p.edges[static_cast<size_t>(s.edge)].name}};
  if (s.from_mm > 0) j["from"] = s.from_mm;
  if (s.to_mm >= 0) j["to"] = s.to_mm;
  return j;
}

}  // namespace

std::string write_stitches_json(const Pattern& pattern, const std::vector<StitchSuggestion>& suggestions) {
  ojson root;
  root["format"] = "tp-stitches";
  root["version"] = 1;
  root["pattern"] = pattern.name;
  root["units"] = "mm";
  ojson stitches = ojson::array();
  for (const StitchSuggestion& s : suggestions)
    for (const Stitch& st : s.stitches) {
      ojson j{{"a", side_json(pattern, st.a)}, {"b", side_json(pattern, st.b)}};
      if (st.same_direction) j["same_direction"] = true;
      if (st.ease_ratio > 0) j["ease"] = st.ease_ratio;
      j["score"] = s.score;
      j["reason"] = s.reason;
      stitches.push_back(std::move(j));
    }
  root["stitches"] = std::move(stitches);
  return root.dump(1) + "\n";
}

Result<std::vector<Stitch>> read_stitches_json(std::string_view text, const std::string& source_name,
                                               const Pattern& pattern) {
  TP_TRY(root, internal::parse_json(text, source_name));
  internal::JsonPath at{source_name, ""};
  TP_CHECK(internal::expect_object(root, at));
  if (const nlohmann::json* f = internal::member(root, "format")) {
    TP_TRY(name, internal::get_string(*f, at / "format"));
    if (name != "tp-stitches")
      return std::unexpected((at / "format").error(ErrorCode::kParse, "expected \"tp-stitches\", found \"" + name + "\""));
  }
  double scale = 1;
  if (const nlohmann::json* u = internal::member(root, "units")) {
    TP_TRY(name, internal::get_string(*u, at / "units"));
    scale = name == "mm" ? 1 : name == "cm" ? 10 : name == "m" ? 1000 : name == "in" ? 25.4 : 0;
    if (scale == 0) return std::unexpected((at / "units").error(ErrorCode::kParse, "unknown unit '" + name + "' (mm, cm, m or in)"));
  }
  if (!internal::member(root, "stitches"))
    return std::unexpected(at.error(ErrorCode::kParse, "a stitches file needs \"stitches\""));
  // Resolve against a copy holding no stitches: the reader appends to pattern.stitches. Physical
  // pieces are named, so no edge stands for an unfolded twin.
  Pattern scratch = pattern;
  scratch.stitches.clear();
  TP_CHECK(internal::read_pattern_json_stitches(root, at, scale, std::map<std::string, bool>{}, scratch));
  return std::move(scratch.stitches);
}

Result<std::vector<Stitch>> load_stitches_json(const std::filesystem::path& path, const Pattern& pattern) {
  TP_TRY(text, internal::read_file(path));
  return read_stitches_json(text, path.string(), pattern);
}

}  // namespace tp::geometry
