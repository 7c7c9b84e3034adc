// geometry/pattern/load_pattern.cpp: format detection and dispatch to the importers.
#include "geometry/pattern/import/load_pattern.h"

#include <algorithm>
#include <cctype>

#include "geometry/pattern/import/dxf_aama.h"
#include "geometry/pattern/import/freesewing_svg.h"
#include "geometry/pattern/import/garmentcode.h"
#include "geometry/pattern/import/obj_garment.h"
#include "geometry/pattern/internal/json_fields.h"
#include "geometry/pattern/internal/read_file.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/pattern_json.h"

namespace tp::geometry {
namespace {

std::string lower_extension(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string_view skip_space(std::string_view s) {
  // A UTF-8 byte order mark and leading white space say nothing about the format.
  if (s.starts_with("\xEF\xBB\xBF")) s.remove_prefix(3);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  return s;
}

Result<PatternFormat> json_kind(std::string_view text, const std::string& name) {
  TP_TRY(root, internal::parse_json(text, name));
  if (root.is_object() && root.contains("pattern")) return PatternFormat::kGarmentCode;
  return PatternFormat::kNative;
}

bool looks_like_dxf(std::string_view s) {
  // "0" then "SECTION" on the next line, with any spacing DXF writers use.
  if (s.empty() || s.front() != '0') return false;
  auto nl = s.find('\n');
  if (nl == std::string_view::npos) return false;
  std::string_view next = skip_space(s.substr(nl + 1));
  return next.starts_with("SECTION");
}

bool looks_like_obj(std::string_view s) {
  // The first meaningful line of an OBJ is a comment or a v/vt/vn/f/o/g/mtllib statement.
  while (!s.empty()) {
    auto nl = s.find('\n');
    std::string_view line = skip_space(s.substr(0, nl));
    s = nl == std::string_view::npos ? std::string_view{} : s.substr(nl + 1);
    if (line.empty() || line.front() == '#') continue;
    for (const char* k : {"v ", "vt ", "vn ", "f ", "o ", "g ", "mtllib ", "usemtl ", "s "})
      if (line.starts_with(k)) return true;
    return false;
  }
  return false;
}

}  // namespace

std::string_view to_string(PatternFormat format) {
  switch (format) {
    case PatternFormat::kNative: return "native";
    case PatternFormat::kGarmentCode: return "garmentcode";
    case PatternFormat::kFreeSewingSvg: return "freesewing-svg";
    case PatternFormat::kDxfAama: return "dxf-aama";
    case PatternFormat::kObjGarment: return "obj-garment";
  }
  return "unknown";
}

Result<PatternFormat> detect_pattern_format(const std::string& source_name, std::string_view text) {
  std::string ext = lower_extension(source_name);
  if (ext == ".svg") return PatternFormat::kFreeSewingSvg;
  if (ext == ".dxf") return PatternFormat::kDxfAama;
  if (ext == ".obj") return PatternFormat::kObjGarment;
  if (ext == ".json") return json_kind(text, source_name);
  std::string_view head = skip_space(text);
  if (head.starts_with("{")) return json_kind(text, source_name);
  if (head.starts_with("<")) return PatternFormat::kFreeSewingSvg;
  if (looks_like_dxf(head)) return PatternFormat::kDxfAama;
  if (looks_like_obj(head)) return PatternFormat::kObjGarment;
  return fail(ErrorCode::kInvalidArgument, source_name + ": not a pattern format this program reads (native or GarmentCode "
                                                         "JSON, FreeSewing SVG, DXF-AAMA, OBJ garment)");
}

Result<Pattern> read_pattern(std::string_view text, const std::string& source_name, const PatternImportOptions& options) {
  TP_TRY(format, detect_pattern_format(source_name, text));
  switch (format) {
    case PatternFormat::kNative: return read_pattern_json(text, source_name, options);
    case PatternFormat::kGarmentCode: return read_garmentcode(text, source_name, options);
    case PatternFormat::kFreeSewingSvg: return read_freesewing_svg(text, source_name, options);
    case PatternFormat::kDxfAama: return read_dxf_aama(text, source_name, options);
    case PatternFormat::kObjGarment: {
      TP_TRY(g, read_obj_garment(text, source_name, options));
      return std::move(g.pattern);
    }
  }
  return fail(ErrorCode::kInvalidArgument, source_name + ": unknown format");
}

Result<Pattern> load_pattern(const std::filesystem::path& path, const PatternImportOptions& options) {
  TP_TRY(text, internal::read_file(path));
  return read_pattern(text, path.string(), options);
}

}  // namespace tp::geometry
