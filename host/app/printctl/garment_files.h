// host/app/printctl/garment_files.h: the files printctl writes for a sewn garment (OBJ with per-piece
// UVs, the body, front/side/back previews), shared by `printctl garment` and `printctl bench garment`.
#pragma once

#include <filesystem>
#include <string>

#include "geometry/body/body_mesh.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"

namespace tp::host::cli {

/// Writes `text` to `path`; the error message naming the file, or empty.
std::string write_text(const std::filesystem::path& path, const std::string& text);

/// Writes `<stem>.obj` (the garment), `<body_stem>.obj` (the body, mm) and `<stem>_front|side|back.png`
/// into `dir` (which must exist). Returns the first error naming its file, or empty.
std::string write_garment_files(const std::filesystem::path& dir, const std::string& stem,
                                const geometry::Pattern& pattern, const geometry::Garment& garment,
                                const geometry::BodyMesh& body, const std::string& body_stem);

}  // namespace tp::host::cli
