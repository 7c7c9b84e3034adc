// rip/image/image_read.cpp: whole images into memory (design images, textures), through the scanline
// reader, turned upright per their EXIF orientation.
#include <spdlog/fmt/fmt.h>

#include "rip/image/image_io.h"
#include "rip/image/internal/orientation.h"
#include "rip/image/internal/scanline_reader.h"

namespace tp::rip {

namespace {

Result<geometry::ImageRgba8> read_whole(const std::string& name, OIIO_NAMESPACE::Filesystem::IOProxy* proxy) {
  auto reader = ScanlineReader::open(name, proxy);
  if (!reader) return std::unexpected(reader.error());
  ScanlineReader& r = **reader;
  if (static_cast<std::int64_t>(r.width_px()) * r.height_px() > kMaxImagePixels)
    return fail(ErrorCode::kImage, fmt::format("{}: {}x{} pixels exceeds the limit of {} pixels", name, r.width_px(),
                                               r.height_px(), kMaxImagePixels));
  geometry::ImageRgba8 img;
  img.width_px = r.width_px();
  img.height_px = r.height_px();
  img.source = name;
  img.pixels.resize(static_cast<size_t>(img.width_px) * img.height_px);
  if (auto s = r.read_rows(img.height_px, img.pixels.data(), img.width_px); !s) return std::unexpected(s.error());
  return apply_exif_orientation(std::move(img), r.orientation());
}

}  // namespace

Result<geometry::ImageRgba8> read_image(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail(ErrorCode::kImage, path.string() + ": no such image file");
  return read_whole(path.string(), nullptr);
}

Result<geometry::ImageRgba8> read_image_from_memory(std::span<const std::uint8_t> bytes, std::string_view name) {
  OIIO_NAMESPACE::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
  return read_whole(std::string(name), &proxy);
}

}  // namespace tp::rip
