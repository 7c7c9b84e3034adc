// geometry/pattern/import/internal/dxf_groups.h: DXF group-code pairs grouped into sections, blocks and entities.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "geometry/common/error.h"

namespace tp::geometry::internal {

/// One group: a code and its value (trimmed), with the line of the code.
struct DxfGroup {
  int code = 0;
  std::string value;
  int line = 0;
};

/// An entity: its type ("LINE", "POLYLINE", ...) and the groups that follow the type group.
/// A POLYLINE carries its VERTEX entities in `vertices` (SEQEND dropped).
struct DxfEntity {
  std::string type;
  std::vector<DxfGroup> groups;
  std::vector<DxfEntity> vertices;
  int line = 0;

  /// First value of `code`, or nullptr.
  const std::string* value(int code) const;
  /// First value of `code` as a number, or `fallback` when absent or not a number.
  double number(int code, double fallback = 0) const;
  /// The layer (group 8), trimmed.
  std::string layer() const;
};

/// A BLOCK: its name (group 2) and entities up to ENDBLK.
struct DxfBlock {
  std::string name;
  std::vector<DxfEntity> entities;
  int line = 0;
};

/// What the pattern importer needs from a DXF file.
struct DxfDocument {
  std::vector<DxfGroup> header;      ///< HEADER groups in order ($INSUNITS is a 9 group then a 70)
  std::vector<DxfBlock> blocks;
  std::vector<DxfEntity> entities;   ///< the ENTITIES section
};

/// Reads group-code/value line pairs (CR LF or LF). Fails (kParse, "file:line: ...") on a group
/// code that is not an integer or a value missing at the end; unknown sections are skipped.
[[nodiscard]] Result<DxfDocument> read_dxf_groups(std::string_view text, const std::string& file);

}  // namespace tp::geometry::internal
