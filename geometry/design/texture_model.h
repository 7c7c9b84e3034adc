// geometry/design/texture_model.h: reading the textured 3D model of a texture-transfer layer
// (a Wavefront OBJ of the same garment, painted in another tool, with its own UVs into an image).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "geometry/common/error.h"
#include "geometry/design/design.h"

namespace tp::geometry {

/// The model's triangles, positions (scaled to mm by `mm_per_unit`) and texture coordinates (as
/// written, 0..1 with v up; values outside wrap when sampled). The image is left for the caller.
/// Fails with kParse naming "file:line" on malformed OBJ, and kDesign when the model has no faces,
/// a face without texture coordinates, or degenerate extent.
[[nodiscard]] Result<TextureTransfer> read_texture_model(std::string_view obj_text, const std::string& source_name,
                                                         double mm_per_unit = 1.0);

/// read_texture_model on a file; kIo naming the path if it cannot be read.
[[nodiscard]] Result<TextureTransfer> load_texture_model(const std::filesystem::path& path, double mm_per_unit = 1.0);

}  // namespace tp::geometry
