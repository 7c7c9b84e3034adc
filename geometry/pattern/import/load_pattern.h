// geometry/pattern/import/load_pattern.h: loading a pattern from any supported file, chosen by extension and content.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/pattern/import/import_options.h"
#include "geometry/pattern/pattern.h"

namespace tp::geometry {

/// The pattern file formats the project reads.
enum class PatternFormat {
  kNative,         ///< the project's JSON format (docs/pattern-format.md)
  kGarmentCode,    ///< GarmentCode specification JSON
  kFreeSewingSvg,  ///< FreeSewing SVG export
  kDxfAama,        ///< DXF-AAMA / ASTM D6673
  kObjGarment,     ///< OBJ garment with texture coordinates in mm (read_obj_garment)
};

/// "native", "garmentcode", "freesewing-svg", "dxf-aama", "obj-garment".
std::string_view to_string(PatternFormat format);

/// The format of a file from its extension (.json, .svg, .dxf, .obj) and, for JSON or an unknown
/// extension, its first bytes: a JSON object with "pattern" is GarmentCode, otherwise native;
/// "<" starts an SVG, a "0" line followed by "SECTION" a DXF, "v"/"vt"/"f" lines an OBJ.
/// Fails (kInvalidArgument, naming the file) when nothing matches.
[[nodiscard]] Result<PatternFormat> detect_pattern_format(const std::string& source_name, std::string_view text);

/// Parses `text` in the detected format. For an OBJ garment only the pattern is returned (use
/// read_obj_garment for the 3D garment too). Errors are the importer's, naming the file.
[[nodiscard]] Result<Pattern> read_pattern(std::string_view text, const std::string& source_name,
                                           const PatternImportOptions& options = {});

/// Reads the file and calls read_pattern; kIo when it cannot be read. The job intake's entry
/// point: validate the result with validate_pattern before use.
[[nodiscard]] Result<Pattern> load_pattern(const std::filesystem::path& path, const PatternImportOptions& options = {});

}  // namespace tp::geometry
