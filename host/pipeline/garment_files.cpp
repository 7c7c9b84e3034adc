// host/pipeline/garment_files.cpp: OBJ and preview files of a sewn garment.
#include "host/pipeline/garment_files.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>

#include "geometry/design/render_piece_image.h"
#include "geometry/garment/garment_obj.h"
#include "geometry/preview/render_preview.h"
#include "host/common/atomic_file.h"
#include "host/pipeline/internal/output_files.h"

namespace tp::host {
namespace {

std::string body_obj(const geometry::BodyMesh& body) {
  std::string out = "# " + body.name + ": body frame, mm (y up, z front, x wearer's left)\n";
  char buf[96];
  for (const auto& v : body.vertices_mm) {
    std::snprintf(buf, sizeof buf, "v %.3f %.3f %.3f\n", v.x, v.y, v.z);
    out += buf;
  }
  for (const auto& t : body.triangles) {
    std::snprintf(buf, sizeof buf, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out += buf;
  }
  return out;
}

// Pixels between neighbouring pieces in the texture (each image has its own 2 px margin too).
constexpr int kAtlasGapPx = 2;
// Share of the texture square the pieces' boxes may fill: shelves waste the rest.
constexpr double kAtlasFill = 0.6;
/// Threads rendering the atlas's pieces (band by band; the pixels do not depend on the count).
constexpr int kAtlasThreads = 2;

}  // namespace

Status write_text_file(const std::filesystem::path& path, const std::string& text) {
  return write_file_atomic(path, text);
}

Result<std::vector<std::string>> write_garment_previews(const std::filesystem::path& dir, const std::string& prefix,
                                                        const geometry::Garment& garment,
                                                        const geometry::BodyMesh* body, rip::PngChannels channels) {
  std::vector<std::string> names;
  for (auto view : {geometry::PreviewView::kFront, geometry::PreviewView::kSide, geometry::PreviewView::kBack}) {
    const std::string name = prefix + geometry::to_string(view) + ".png";
    if (auto st = internal::write_png_checked(dir / name, geometry::render_preview(garment, body, view), channels); !st)
      return fail(st.error());
    names.push_back(name);
  }
  return names;
}

Result<std::vector<std::string>> write_garment_print_previews(const std::filesystem::path& dir,
                                                              const std::string& prefix,
                                                              const geometry::Garment& garment,
                                                              const geometry::BodyMesh* body,
                                                              const geometry::PieceRenderer& renderer, double dpi) {
  std::vector<geometry::PieceTexture> textures(garment.pieces.size());
  for (size_t i = 0; i < garment.pieces.size(); ++i) {
    const int piece = garment.pieces[i].piece;
    if (piece < 0 || piece >= renderer.piece_count()) continue;
    if (garment.pieces[i].vertex_3d.empty()) continue;  // left out of this garment (garment_without)
    geometry::PieceImage img = geometry::render_piece_image(renderer, piece, dpi);
    if (img.image.width_px <= 0 || img.image.height_px <= 0) continue;
    // The print over white fabric: the preview shows the garment as it comes off the press.
    for (geometry::Rgba8& p : img.image.pixels) {
      const auto over = [a = p.a](std::uint8_t c) {
        return static_cast<std::uint8_t>((c * a + 255 * (255 - a) + 127) / 255);
      };
      p = {over(p.r), over(p.g), over(p.b), 255};
    }
    textures[i] = {std::move(img.image), img.pixel_to_piece_mm.inverse()};
  }
  geometry::PreviewOptions o;
  o.textures = &textures;
  std::vector<std::string> names;
  for (auto view : {geometry::PreviewView::kFront, geometry::PreviewView::kSide, geometry::PreviewView::kBack}) {
    const std::string name = prefix + geometry::to_string(view) + ".png";
    if (auto st = internal::write_png_checked(dir / name, geometry::render_preview(garment, body, view, o),
                                              rip::PngChannels::kRgba);
        !st)
      return fail(st.error());
    names.push_back(name);
  }
  return names;
}

Status write_garment_files(const std::filesystem::path& dir, const std::string& stem, const geometry::Pattern& pattern,
                           const geometry::Garment& garment, const geometry::BodyMesh& body,
                           const std::string& body_stem) {
  if (auto st = write_text_file(dir / (stem + ".obj"), geometry::garment_to_obj(pattern, garment)); !st) return st;
  if (auto st = write_text_file(dir / (body_stem + ".obj"), body_obj(body)); !st) return st;
  auto previews = write_garment_previews(dir, stem + "_", garment, &body, rip::PngChannels::kRgbOverWhite);
  if (!previews) return fail(previews.error());
  return {};
}

Result<TexturedGarmentFiles> write_textured_garment(const std::filesystem::path& dir, const std::string& stem,
                                                    const geometry::Pattern& pattern, const geometry::Garment& garment,
                                                    const geometry::PieceRenderer& renderer, double max_dpi) {
  const double mm_per_inch = 25.4;
  // Resolution: the pieces' boxes fill at most kAtlasFill of the largest texture, none wider than it.
  double area_mm2 = 0, widest_mm = 0;
  for (const geometry::GarmentPiece& gp : garment.pieces) {
    if (gp.piece < 0 || gp.piece >= renderer.piece_count()) continue;
    const geometry::Box2 b = geometry::bounds(renderer.cut_outline_mm(gp.piece));
    if (b.empty()) continue;
    area_mm2 += b.width() * b.height();
    widest_mm = std::max({widest_mm, b.width(), b.height()});
  }
  double dpi = max_dpi > 0 ? max_dpi : 50;
  if (area_mm2 > 0) {
    const double side_px = kGarmentTextureMaxSidePx;
    dpi = std::min(dpi, mm_per_inch * std::sqrt(kAtlasFill * side_px * side_px / area_mm2));
    dpi = std::min(dpi, mm_per_inch * (side_px - 16) / widest_mm);
  }
  dpi = std::floor(dpi * 100) / 100;  // a round figure for the report and pHYs

  // Each piece's print, then shelves: tallest first (ties by piece order, so the layout repeats).
  struct Island {
    int piece;
    geometry::PieceImage image;
    int x = 0, y = 0;
  };
  std::vector<Island> islands;
  int used_w = 1, height = 1;
  // Shelves can leave the texture taller than wide: then the pieces go in again, smaller.
  for (int attempt = 0; attempt < 4; ++attempt) {
    islands.clear();
    double island_area = 0;
    std::vector<int> pieces;
    for (const geometry::GarmentPiece& gp : garment.pieces)
      if (gp.piece >= 0 && gp.piece < renderer.piece_count()) pieces.push_back(gp.piece);
    auto images = geometry::render_piece_images(renderer, pieces, dpi, kAtlasThreads);
    for (size_t k = 0; k < pieces.size(); ++k) {
      geometry::PieceImage& img = images[k];
      if (img.image.width_px <= 0 || img.image.height_px <= 0) continue;
      island_area += static_cast<double>(img.image.width_px + kAtlasGapPx) * (img.image.height_px + kAtlasGapPx);
      islands.push_back({pieces[k], std::move(img)});
    }
    std::vector<size_t> order(islands.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return islands[a].image.image.height_px > islands[b].image.image.height_px;
    });
    int width = 1;
    for (const Island& is : islands) width = std::max(width, is.image.image.width_px);
    width = std::min(kGarmentTextureMaxSidePx,
                     std::max(width, static_cast<int>(std::ceil(std::sqrt(island_area / kAtlasFill)))));
    int x = 0, y = 0, shelf = 0;
    used_w = 1;
    for (size_t i : order) {
      Island& is = islands[i];
      if (x > 0 && x + is.image.image.width_px > width) {
        x = 0;
        y += shelf + kAtlasGapPx;
        shelf = 0;
      }
      is.x = x;
      is.y = y;
      x += is.image.image.width_px + kAtlasGapPx;
      used_w = std::max(used_w, is.x + is.image.image.width_px);
      shelf = std::max(shelf, is.image.image.height_px);
    }
    height = std::max(1, y + shelf);
    if (height <= kGarmentTextureMaxSidePx) break;
    dpi = std::floor(dpi * 0.97 * std::sqrt(static_cast<double>(kGarmentTextureMaxSidePx) / height) * 100) / 100;
  }

  geometry::ImageRgba8 atlas;
  atlas.width_px = used_w;
  atlas.height_px = height;
  atlas.pixels.assign(static_cast<size_t>(used_w) * height, geometry::Rgba8{255, 255, 255, 0});
  geometry::GarmentTexture tex{stem + ".mtl", "print", stem + ".png", used_w, height, {}};
  tex.piece_mm_to_atlas_px.resize(pattern.pieces.size());
  for (const Island& is : islands) {
    const geometry::ImageRgba8& src = is.image.image;
    for (int r = 0; r < src.height_px; ++r) std::copy_n(&src.at(0, r), src.width_px, &atlas.at(is.x, is.y + r));
    if (static_cast<size_t>(is.piece) < tex.piece_mm_to_atlas_px.size())
      tex.piece_mm_to_atlas_px[static_cast<size_t>(is.piece)] =
          geometry::Affine2::translation({static_cast<double>(is.x), static_cast<double>(is.y)})
              .compose(is.image.pixel_to_piece_mm.inverse());
  }

  TexturedGarmentFiles files{stem + ".obj", stem + ".mtl", stem + ".png", used_w, height, dpi, {}};
  for (const Island& is : islands)
    files.islands.push_back(
        {is.piece, is.x, is.y, is.image.image.width_px, is.image.image.height_px, is.image.pixel_to_piece_mm});
  if (auto st = internal::write_png_checked(dir / files.texture, atlas, rip::PngChannels::kRgbOverWhite, dpi); !st)
    return fail(st.error());
  if (auto st = write_text_file(dir / files.mtl, geometry::garment_mtl(tex)); !st) return fail(st.error());
  if (auto st = write_text_file(dir / files.obj, geometry::garment_to_obj(pattern, garment, &tex)); !st)
    return fail(st.error());
  return files;
}

}  // namespace tp::host
