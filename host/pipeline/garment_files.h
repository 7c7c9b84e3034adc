// host/pipeline/garment_files.h: the files written for a sewn garment (its OBJ with per-piece UVs,
// the body, front/side/back previews): by the pipeline's garment stage and by `printctl garment`
// and `printctl bench garment`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "geometry/body/body_mesh.h"
#include "geometry/design/piece_renderer.h"
#include "geometry/garment/garment.h"
#include "geometry/pattern/pattern.h"
#include "host/common/error.h"
#include "rip/image/image_io.h"

namespace tp::host {

/// Writes `text` to `path`. Fails (kIo) naming the file.
[[nodiscard]] Status write_text_file(const std::filesystem::path& path, const std::string& text);

/// Writes `<prefix>front.png`, `<prefix>side.png` and `<prefix>back.png` into `dir`: the garment
/// (pieces coloured apart) on `body` when given. Returns the file names; fails (kIo) naming the file.
[[nodiscard]] Result<std::vector<std::string>> write_garment_previews(const std::filesystem::path& dir,
                                                                      const std::string& prefix,
                                                                      const geometry::Garment& garment,
                                                                      const geometry::BodyMesh* body,
                                                                      rip::PngChannels channels);

/// `<stem>.obj` (the garment), `<body_stem>.obj` (the body in mm, body frame) and the previews
/// `<stem>_front|side|back.png` (over white) into `dir`, which must exist.
[[nodiscard]] Status write_garment_files(const std::filesystem::path& dir, const std::string& stem,
                                         const geometry::Pattern& pattern, const geometry::Garment& garment,
                                         const geometry::BodyMesh& body, const std::string& body_stem);

/// Where one piece's image lies in the garment texture.
struct AtlasIsland {
  int piece = -1;
  int x_px = 0, y_px = 0, width_px = 0, height_px = 0;  ///< the piece image's rectangle in the texture
  geometry::Affine2 pixel_to_piece_mm;                  ///< of the piece image (render_piece_image's)
};

/// What write_textured_garment wrote.
struct TexturedGarmentFiles {
  std::string obj, mtl, texture;  ///< file names in the output folder
  int texture_width_px = 0, texture_height_px = 0;
  double texture_dpi = 0;            ///< resolution of the pieces in the texture
  std::vector<AtlasIsland> islands;  ///< the layout, so the same texture can be rendered again
};

/// Largest side of the garment texture, pixels (what real-time viewers load without complaint).
inline constexpr int kGarmentTextureMaxSidePx = 4096;

/// The printed garment for 3D tools: every piece's print rendered at one resolution (at most
/// `max_dpi`, lower when the pieces would not fit a kGarmentTextureMaxSidePx square), packed in
/// shelves into `<stem>.png` (over white fabric, pHYs at that resolution), `<stem>.mtl` naming it
/// as the diffuse map, and `<stem>.obj` whose texture coordinates point into it (normalised to
/// [0, 1]; positions in mm, stated in the file). Fails (kIo) naming the file.
[[nodiscard]] Result<TexturedGarmentFiles> write_textured_garment(
    const std::filesystem::path& dir, const std::string& stem, const geometry::Pattern& pattern,
    const geometry::Garment& garment, const geometry::PieceRenderer& renderer, double max_dpi);

/// Writes `<prefix>front.png`, `<prefix>side.png` and `<prefix>back.png`: the garment on `body`
/// (when given) wearing its print, each piece's print (rendered at `dpi`, over white fabric)
/// mapped through the piece's 2D mesh. Returns the file names; fails (kIo) naming the file.
[[nodiscard]] Result<std::vector<std::string>> write_garment_print_previews(
    const std::filesystem::path& dir, const std::string& prefix, const geometry::Garment& garment,
    const geometry::BodyMesh* body, const geometry::PieceRenderer& renderer, double dpi);

}  // namespace tp::host
