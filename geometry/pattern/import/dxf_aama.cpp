// geometry/pattern/dxf_aama.cpp: DXF-AAMA blocks (layers, polylines, texts) to pattern pieces.
#include "geometry/pattern/import/dxf_aama.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "geometry/pattern/import/internal/dxf_groups.h"
#include "geometry/pattern/import/internal/dxf_piece.h"
#include "geometry/pattern/internal/read_file.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/unfold.h"

namespace tp::geometry {
namespace {

using internal::DxfDocument;
using internal::DxfEntity;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// "Units: METRIC" style text anywhere, else the header's $INSUNITS / $MEASUREMENT.
double unit_mm(const DxfDocument& doc, double fallback) {
  auto from_texts = [&](const std::vector<DxfEntity>& ents) -> double {
    for (const DxfEntity& e : ents) {
      if (e.type != "TEXT" && e.type != "MTEXT") continue;
      const std::string* v = e.value(1);
      if (!v) continue;
      std::string u = upper(*v);
      auto at = u.find("UNITS");
      if (at == std::string::npos) continue;
      if (u.find("METRIC", at) != std::string::npos) return 1.0;
      if (u.find("ENGLISH", at) != std::string::npos || u.find("INCH", at) != std::string::npos) return 25.4;
    }
    return 0;
  };
  if (double u = from_texts(doc.entities); u > 0) return u;
  for (const auto& b : doc.blocks)
    if (double u = from_texts(b.entities); u > 0) return u;
  // Header variables: a 9 group names the variable, the next group holds its value.
  for (size_t i = 0; i + 1 < doc.header.size(); ++i) {
    if (doc.header[i].code != 9) continue;
    const std::string& var = doc.header[i].value;
    const std::string& val = doc.header[i + 1].value;
    if (var == "$INSUNITS") {
      if (val == "1") return 25.4;
      if (val == "4") return 1.0;
      if (val == "5") return 10.0;
      if (val == "6") return 1000.0;
    }
  }
  for (size_t i = 0; i + 1 < doc.header.size(); ++i)
    if (doc.header[i].code == 9 && doc.header[i].value == "$MEASUREMENT")
      return doc.header[i + 1].value == "0" ? 25.4 : 1.0;
  return fallback;
}

}  // namespace

Result<Pattern> read_dxf_aama(std::string_view text, const std::string& source_name, const PatternImportOptions& options) {
  TP_TRY(doc, internal::read_dxf_groups(text, source_name));
  const double unit = unit_mm(doc, options.dxf_default_unit_mm);
  Pattern pattern;
  pattern.name = std::filesystem::path(source_name).stem().string();
  std::map<std::string, int> used_names;
  for (const internal::DxfBlock& block : doc.blocks) {
    if (!block.name.empty() && block.name.front() == '*') continue;
    TP_TRY(dp, internal::build_dxf_piece(block, unit, source_name, options, pattern.warnings));
    if (dp.piece.edges.empty()) continue;
    if (pattern.size.empty()) pattern.size = dp.size;
    Piece piece = std::move(dp.piece);
    // Piece names must be unique; a repeated name gets a suffix (and a warning).
    if (used_names[piece.name]++ > 0) {
      std::string renamed = piece.name + "_" + std::to_string(used_names[piece.name]);
      pattern.warnings.push_back(source_name + ":" + std::to_string(block.line) + ": second piece named '" + piece.name +
                                 "' renamed '" + renamed + "'");
      piece.name = renamed;
    }
    if (piece.fold_edge && options.unfold_cut_on_fold) {
      auto whole = unfold_piece(piece, *piece.fold_edge);
      if (!whole) return std::unexpected(whole.error().with_context(source_name + ":" + std::to_string(block.line)));
      piece = std::move(*whole);
    }
    int qty = options.expand_quantity ? dp.quantity : 1;
    for (Piece& p : expand_copies(piece, qty, dp.mirror_pairs, options.drafted_side)) pattern.pieces.push_back(std::move(p));
  }
  if (pattern.pieces.empty())
    return fail(ErrorCode::kInvalidPattern, source_name + ": no piece (a BLOCK with a boundary on layer 1 or a sew line on layer 14)");
  return pattern;
}

Result<Pattern> load_dxf_aama(const std::filesystem::path& path, const PatternImportOptions& options) {
  TP_TRY(text, internal::read_file(path));
  return read_dxf_aama(text, path.string(), options);
}

}  // namespace tp::geometry
