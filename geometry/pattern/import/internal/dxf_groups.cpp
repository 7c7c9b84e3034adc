// geometry/pattern/internal/dxf_groups.cpp: the DXF group-pair reader (sections, blocks, entities).
#include "geometry/pattern/import/internal/dxf_groups.h"

#include <charconv>
#include <cmath>

namespace tp::geometry::internal {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

}  // namespace

const std::string* DxfEntity::value(int code) const {
  for (const DxfGroup& g : groups)
    if (g.code == code) return &g.value;
  return nullptr;
}

double DxfEntity::number(int code, double fallback) const {
  const std::string* v = value(code);
  if (!v) return fallback;
  double out = 0;
  auto r = std::from_chars(v->data(), v->data() + v->size(), out);
  if (r.ec != std::errc() || !std::isfinite(out)) return fallback;
  return out;
}

std::string DxfEntity::layer() const {
  const std::string* v = value(8);
  return v ? *v : std::string();
}

Result<DxfDocument> read_dxf_groups(std::string_view text, const std::string& file) {
  // All groups first: code line, value line.
  std::vector<DxfGroup> groups;
  size_t pos = 0;
  int line = 0;
  auto next_line = [&](std::string_view& out) {
    if (pos >= text.size()) return false;
    size_t nl = text.find('\n', pos);
    size_t end = nl == std::string_view::npos ? text.size() : nl;
    out = text.substr(pos, end - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++line;
    return true;
  };
  std::string_view code_line, value_line;
  while (next_line(code_line)) {
    std::string_view c = trim(code_line);
    if (c.empty() && pos >= text.size()) break;
    int code_at = line;
    int code = 0;
    auto r = std::from_chars(c.data(), c.data() + c.size(), code);
    if (r.ec != std::errc() || r.ptr != c.data() + c.size())
      return fail(ErrorCode::kParse, file + ":" + std::to_string(code_at) + ": group code '" +
                                         std::string(c.substr(0, 20)) + "' is not an integer");
    if (!next_line(value_line))
      return fail(ErrorCode::kParse, file + ":" + std::to_string(code_at) + ": group code " + std::to_string(code) +
                                         " has no value (file ends)");
    groups.push_back(DxfGroup{code, std::string(trim(value_line)), code_at});
  }

  // Then structure: SECTION/ENDSEC, BLOCK/ENDBLK, entities started by 0 groups.
  DxfDocument doc;
  std::string section;
  DxfBlock* block = nullptr;
  DxfEntity* polyline = nullptr;   // the open POLYLINE collecting VERTEX entities
  DxfEntity* current = nullptr;    // the entity collecting groups
  for (size_t i = 0; i < groups.size(); ++i) {
    const DxfGroup& g = groups[i];
    if (g.code != 0) {
      if (section == "HEADER") doc.header.push_back(g);
      else if (current) current->groups.push_back(g);
      else if (block && g.code == 2 && block->name.empty()) block->name = g.value;
      continue;
    }
    const std::string& type = g.value;
    current = nullptr;
    if (type == "SECTION") {
      // The section name is the next group (code 2).
      section = (i + 1 < groups.size() && groups[i + 1].code == 2) ? groups[i + 1].value : "";
      if (i + 1 < groups.size() && groups[i + 1].code == 2) ++i;
      block = nullptr;
      polyline = nullptr;
      continue;
    }
    if (type == "ENDSEC" || type == "EOF") {
      section.clear();
      block = nullptr;
      polyline = nullptr;
      continue;
    }
    if (section == "BLOCKS" && type == "BLOCK") {
      doc.blocks.push_back(DxfBlock{"", {}, g.line});
      block = &doc.blocks.back();
      polyline = nullptr;
      continue;
    }
    if (section == "BLOCKS" && type == "ENDBLK") {
      block = nullptr;
      polyline = nullptr;
      continue;
    }
    std::vector<DxfEntity>* list = nullptr;
    if (section == "BLOCKS" && block) list = &block->entities;
    else if (section == "ENTITIES") list = &doc.entities;
    if (!list) continue;
    if (type == "VERTEX" && polyline) {
      polyline->vertices.push_back(DxfEntity{type, {}, {}, g.line});
      current = &polyline->vertices.back();
      continue;
    }
    if (type == "SEQEND") {
      polyline = nullptr;
      continue;
    }
    list->push_back(DxfEntity{type, {}, {}, g.line});
    current = &list->back();
    polyline = type == "POLYLINE" ? current : nullptr;
  }
  return doc;
}

}  // namespace tp::geometry::internal
