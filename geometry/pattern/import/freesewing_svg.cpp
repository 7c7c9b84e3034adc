// geometry/pattern/freesewing_svg.cpp: walking a FreeSewing SVG's elements into parts, then pieces.
#include "geometry/pattern/import/freesewing_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "geometry/pattern/import/internal/svg_part.h"
#include "geometry/pattern/import/svg_path.h"
#include "geometry/pattern/import/xml_tokenizer.h"
#include "geometry/pattern/internal/read_file.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/unfold.h"

namespace tp::geometry {
namespace {

using internal::SvgPart;

/// Deepest element nesting followed; deeper markup is read as if flattened (no pattern needs it).
constexpr size_t kMaxDepth = 256;

struct Frame {
  std::string name;
  Affine2 to_part;       ///< element coordinates to part coordinates
  int part = -1;         ///< index of the part this element is in, or -1
  bool is_part_root = false;
  bool in_text = false;
};

std::string strip_ns(const std::string& name) {
  auto colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

/// "fs-stack-penelope.back-part-penelope.back" -> "penelope.back"; "" if not a part group.
std::string part_of_group_id(const std::string& id) {
  if (id.rfind("fs-stack-", 0) != 0) return "";
  auto at = id.find("-part-");
  return at == std::string::npos ? "" : id.substr(at + 6);
}

Result<std::vector<SvgPart>> collect_parts(std::string_view text, const std::string& file, std::vector<std::string>& warnings) {
  std::vector<SvgPart> parts;
  std::vector<Frame> stack;
  XmlTokenizer tok(text);
  XmlToken t;
  std::string text_buffer;
  while (tok.next(t)) {
    if (t.kind == XmlTokenKind::kText) {
      if (!stack.empty() && stack.back().in_text) text_buffer += t.text;
      continue;
    }
    std::string name = strip_ns(t.name);
    if (t.kind == XmlTokenKind::kEndTag) {
      // Pop up to the matching element; an end tag matching nothing open is ignored.
      auto it = std::find_if(stack.rbegin(), stack.rend(), [&](const Frame& f) { return f.name == name; });
      if (it == stack.rend()) continue;
      while (!stack.empty()) {
        Frame f = stack.back();
        stack.pop_back();
        if (f.name == "text" && f.part >= 0 && (stack.empty() || !stack.back().in_text)) {
          parts[f.part].texts.push_back(text_buffer);
          text_buffer.clear();
        }
        if (f.name == name) break;
      }
      continue;
    }
    Frame parent = stack.empty() ? Frame{} : stack.back();
    Frame f{name, parent.to_part, parent.part, false, parent.in_text};
    if (const std::string* tr = find_attribute(t, "transform")) {
      auto m = parse_svg_transform(*tr);
      if (!m) {
        warnings.push_back(file + ":" + std::to_string(t.line) + ": <" + name + "> " + m.error().message + "; ignored");
      } else {
        f.to_part = f.to_part.compose(*m);
      }
    }
    if (name == "g") {
      const std::string* id = find_attribute(t, "id");
      std::string part = id ? part_of_group_id(*id) : "";
      if (!part.empty()) {
        // Part coordinates are the drafting coordinates: the part group's own placement on the
        // sheet and everything above it are left out.
        SvgPart p;
        p.group_id = *id;
        p.name = part.substr(part.rfind('.') == std::string::npos ? 0 : part.rfind('.') + 1);
        p.line = t.line;
        parts.push_back(std::move(p));
        f.part = static_cast<int>(parts.size()) - 1;
        f.to_part = Affine2{};
        f.is_part_root = true;
      }
    }
    if (f.part >= 0 && name == "path") {
      internal::SvgPathElement pe;
      auto get = [&](const char* a) {
        const std::string* v = find_attribute(t, a);
        return v ? *v : std::string();
      };
      pe.id = get("id");
      pe.cls = get("class");
      pe.d = get("d");
      pe.data_text = get("data-text");
      pe.marker_start = get("marker-start");
      pe.to_part = f.to_part;
      pe.line = t.line;
      parts[f.part].paths.push_back(std::move(pe));
    }
    if (f.part >= 0 && name == "use") {
      const std::string* href = find_attribute(t, "xlink:href");
      if (!href) href = find_attribute(t, "href");
      if (href && (*href == "#notch" || *href == "#bnotch")) {
        // <use x y> places the symbol's origin at transform * translate(x, y).
        double x = 0, y = 0;
        if (const std::string* xs = find_attribute(t, "x")) x = std::strtod(xs->c_str(), nullptr);
        if (const std::string* ys = find_attribute(t, "y")) y = std::strtod(ys->c_str(), nullptr);
        Vec2 at = f.to_part.apply({std::isfinite(x) ? x : 0, std::isfinite(y) ? y : 0});
        parts[f.part].notches.push_back(internal::SvgNotchMark{at, *href == "#bnotch", t.line});
      }
    }
    if (name == "text") {
      if (!parent.in_text) text_buffer.clear();
      f.in_text = true;
    }
    if (!t.self_closing && stack.size() < kMaxDepth) stack.push_back(std::move(f));
  }
  return parts;
}

}  // namespace

Result<Pattern> read_freesewing_svg(std::string_view text, const std::string& source_name, const PatternImportOptions& options) {
  Pattern pattern;
  TP_TRY(parts, collect_parts(text, source_name, pattern.warnings));
  if (parts.empty())
    return fail(ErrorCode::kInvalidPattern, source_name + ": no FreeSewing part groups (<g id=\"fs-stack-...-part-...\">)");
  for (const SvgPart& part : parts) {
    TP_TRY(sp, internal::build_svg_piece(part, source_name, options, pattern.warnings));
    if (sp.piece.edges.empty()) continue;
    Piece piece = std::move(sp.piece);
    if (piece.fold_edge && options.unfold_cut_on_fold) {
      auto whole = unfold_piece(piece, *piece.fold_edge);
      if (!whole)
        return std::unexpected(whole.error().with_context(source_name + ":" + std::to_string(part.line) + ": part '" + part.name + "'"));
      piece = std::move(*whole);
    }
    int qty = options.expand_quantity ? sp.quantity : 1;
    for (Piece& p : expand_copies(piece, qty, sp.mirror_pairs, options.drafted_side)) pattern.pieces.push_back(std::move(p));
  }
  if (pattern.pieces.empty())
    return fail(ErrorCode::kInvalidPattern, source_name + ": no part has a closed seam line (a closed path of class 'fabric')");
  // Design name from the part ids ("penelope"), size from the rest of the file name.
  const std::string& gid = parts.front().group_id;
  std::string design = gid.substr(9, gid.find('.') == std::string::npos ? std::string::npos : gid.find('.') - 9);
  pattern.name = design;
  std::string stem = std::filesystem::path(source_name).stem().string();
  if (stem.rfind(design + "-", 0) == 0) pattern.size = stem.substr(design.size() + 1);
  return pattern;
}

Result<Pattern> load_freesewing_svg(const std::filesystem::path& path, const PatternImportOptions& options) {
  TP_TRY(text, internal::read_file(path));
  return read_freesewing_svg(text, path.string(), options);
}

}  // namespace tp::geometry
