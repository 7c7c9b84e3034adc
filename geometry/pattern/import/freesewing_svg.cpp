// geometry/pattern/import/freesewing_svg.cpp: walking a FreeSewing SVG's elements into parts, then pieces.
#include "geometry/pattern/import/freesewing_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <pugixml.hpp>

#include "geometry/pattern/import/internal/svg_part.h"
#include "geometry/pattern/import/svg_path.h"
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
  Affine2 to_part;  ///< element coordinates to part coordinates
  int part = -1;    ///< index of the part this element is in, or -1
  bool in_text = false;
};

std::string strip_ns(std::string_view name) {
  auto colon = name.rfind(':');
  return std::string(colon == std::string_view::npos ? name : name.substr(colon + 1));
}

/// "fs-stack-penelope.back-part-penelope.back" -> "penelope.back"; "" if not a part group.
std::string part_of_group_id(const std::string& id) {
  if (id.rfind("fs-stack-", 0) != 0) return "";
  auto at = id.find("-part-");
  return at == std::string::npos ? "" : id.substr(at + 6);
}

/// 1-based line of a byte offset into the text, from the offsets where lines start.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text) {
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }
  [[nodiscard]] int line_of(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    auto it = std::upper_bound(starts_.begin(), starts_.end(), static_cast<size_t>(offset));
    return static_cast<int>(it - starts_.begin()) + 1;
  }

 private:
  std::vector<size_t> starts_;
};

/// `name`'s value on `node`, or nullptr when absent.
const char* find_attribute(const pugi::xml_node& node, const char* name) {
  pugi::xml_attribute a = node.attribute(name);
  return a ? a.value() : nullptr;
}

/// All character data (text and CDATA) below `node`, in document order.
void append_text(const pugi::xml_node& node, std::string& out) {
  for (pugi::xml_node n = node.first_child(); n;) {
    if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata) out += n.value();
    if (n.first_child()) {
      n = n.first_child();
      continue;
    }
    while (n && n != node && !n.next_sibling()) n = n.parent();
    if (!n || n == node) break;
    n = n.next_sibling();
  }
}

/// What one element adds to the parts: a new part (part group), a seam/notch path, a notch mark,
/// a text. `f` is the element's frame, filled from its parent's.
void visit_element(const pugi::xml_node& node, Frame& f, const LineIndex& lines, const std::string& file,
                   std::vector<SvgPart>& parts, std::vector<std::string>& warnings) {
  const std::string& name = f.name;
  int line = lines.line_of(node.offset_debug());
  if (const char* tr = find_attribute(node, "transform")) {
    auto m = parse_svg_transform(tr);
    if (!m) {
      warnings.push_back(file + ":" + std::to_string(line) + ": <" + name + "> " + m.error().message + "; ignored");
    } else {
      f.to_part = f.to_part.compose(*m);
    }
  }
  if (name == "g") {
    const char* id = find_attribute(node, "id");
    std::string part = id ? part_of_group_id(id) : "";
    if (!part.empty()) {
      // Part coordinates are the drafting coordinates: the part group's own placement on the
      // sheet and everything above it are left out.
      SvgPart p;
      p.group_id = id;
      p.name = part.substr(part.rfind('.') == std::string::npos ? 0 : part.rfind('.') + 1);
      p.line = line;
      parts.push_back(std::move(p));
      f.part = static_cast<int>(parts.size()) - 1;
      f.to_part = Affine2{};
    }
  }
  if (f.part >= 0 && name == "path") {
    internal::SvgPathElement pe;
    auto get = [&](const char* a) { return std::string(node.attribute(a).value()); };
    pe.id = get("id");
    pe.cls = get("class");
    pe.d = get("d");
    pe.data_text = get("data-text");
    pe.marker_start = get("marker-start");
    pe.to_part = f.to_part;
    pe.line = line;
    parts[f.part].paths.push_back(std::move(pe));
  }
  if (f.part >= 0 && name == "use") {
    const char* href = find_attribute(node, "xlink:href");
    if (!href) href = find_attribute(node, "href");
    if (href && (std::string_view(href) == "#notch" || std::string_view(href) == "#bnotch")) {
      // <use x y> places the symbol's origin at transform * translate(x, y).
      double x = 0, y = 0;
      if (const char* xs = find_attribute(node, "x")) x = std::strtod(xs, nullptr);
      if (const char* ys = find_attribute(node, "y")) y = std::strtod(ys, nullptr);
      Vec2 at = f.to_part.apply({std::isfinite(x) ? x : 0, std::isfinite(y) ? y : 0});
      parts[f.part].notches.push_back(internal::SvgNotchMark{at, std::string_view(href) == "#bnotch", line});
    }
  }
  if (name == "text" && !f.in_text) {
    // One text per outermost <text>, with the character data of its <tspan>s.
    f.in_text = true;
    if (f.part >= 0) {
      std::string text;
      append_text(node, text);
      parts[f.part].texts.push_back(std::move(text));
    }
  }
}

Result<std::vector<SvgPart>> collect_parts(std::string_view text, const std::string& file,
                                           std::vector<std::string>& warnings) {
  pugi::xml_document doc;
  pugi::xml_parse_result parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_ws_pcdata, pugi::encoding_utf8);
  LineIndex lines(text);
  if (!parsed) {
    return fail(ErrorCode::kParse, file + ":" + std::to_string(lines.line_of(parsed.offset)) +
                                       ": not well-formed XML: " + parsed.description() + " (byte " +
                                       std::to_string(parsed.offset) + ")");
  }
  std::vector<SvgPart> parts;
  // Depth-first over the elements without recursion; frames deeper than kMaxDepth share their
  // ancestor's frame.
  std::vector<Frame> stack;
  size_t depth = 0;  // elements entered above `n`; the stack holds the first kMaxDepth of them
  pugi::xml_node n = doc.first_child();
  while (n) {
    if (n.type() == pugi::node_element) {
      Frame f = stack.empty() ? Frame{} : stack.back();
      f.name = strip_ns(n.name());
      visit_element(n, f, lines, file, parts, warnings);
      if (n.first_child()) {
        if (stack.size() < kMaxDepth) stack.push_back(std::move(f));
        ++depth;
        n = n.first_child();
        continue;
      }
    }
    // Next in document order: the next sibling, else the next sibling of the nearest ancestor.
    while (n && !n.next_sibling()) {
      n = n.parent();
      if (n == doc) n = pugi::xml_node();
      if (n) {
        if (stack.size() == depth) stack.pop_back();
        --depth;
      }
    }
    if (n) n = n.next_sibling();
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
