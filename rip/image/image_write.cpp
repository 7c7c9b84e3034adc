// rip/image/image_write.cpp: PNG and multi-channel TIFF output through OpenImageIO.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <spdlog/fmt/fmt.h>

#include "rip/image/image_io.h"
#include "rip/image/internal/tiff_channels.h"
#include "rip/image/tiff_band_writer.h"

namespace tp::rip {

namespace OIIO = OIIO_NAMESPACE;

namespace {

// Encodes in memory and writes the file with every write(2) checked: OIIO's file writers can
// drop a failed fwrite (a full disk left empty or truncated PNGs without an error).
Status write_whole(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const std::uint8_t* data) {
  const std::string name = path.string();
  auto out = OIIO::ImageOutput::create(name);
  if (!out) return fail(ErrorCode::kIo, fmt::format("{}: cannot create image writer: {}", name, OIIO::geterror()));
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput vec(bytes);
  const bool in_memory = out->supports("ioproxy");
  if (in_memory) out->set_ioproxy(&vec);
  if (!out->open(name, spec))
    return fail(ErrorCode::kIo, fmt::format("{}: cannot open for writing: {}", name, out->geterror()));
  if (!out->write_image(OIIO::TypeDesc::UINT8, data)) {
    std::string why = out->geterror();
    out->close();
    return fail(ErrorCode::kIo, fmt::format("{}: cannot write image: {}", name, why));
  }
  if (!out->close()) return fail(ErrorCode::kIo, fmt::format("{}: cannot finish image: {}", name, out->geterror()));
  if (!in_memory) return {};
  int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return fail(ErrorCode::kIo, fmt::format("{}: cannot create: {}", name, std::strerror(errno)));
  size_t off = 0;
  int err = 0;
  while (off < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + off, bytes.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      err = errno;
      break;
    }
    off += static_cast<size_t>(n);
  }
  if (::close(fd) != 0 && err == 0) err = errno;
  // The partial file is left for the caller to remove (host/ writes to a temporary name).
  if (err != 0) {
    return fail(ErrorCode::kIo, fmt::format("{}: {}{}", name, std::strerror(err), err == ENOSPC ? " (ENOSPC)" : ""));
  }
  return {};
}

/// RGB over white fabric: c' = c*a + 255*(1-a), rounded.
std::vector<std::uint8_t> over_white(const geometry::ImageRgba8& image) {
  const size_t n = image.pixels.size();
  std::vector<std::uint8_t> rgb(n * 3);
  for (size_t i = 0; i < n; ++i) {
    const geometry::Rgba8 p = image.pixels[i];
    const unsigned a = p.a, ia = 255 - a;
    rgb[3 * i + 0] = static_cast<std::uint8_t>((p.r * a + 255 * ia + 127) / 255);
    rgb[3 * i + 1] = static_cast<std::uint8_t>((p.g * a + 255 * ia + 127) / 255);
    rgb[3 * i + 2] = static_cast<std::uint8_t>((p.b * a + 255 * ia + 127) / 255);
  }
  return rgb;
}

Status check_size(const std::filesystem::path& path, const geometry::ImageRgba8& image) {
  const size_t n = static_cast<size_t>(std::max(image.width_px, 0)) * std::max(image.height_px, 0);
  if (image.width_px <= 0 || image.height_px <= 0 || image.pixels.size() != n)
    return fail(ErrorCode::kInvalidArgument, fmt::format("{}: image is {}x{} but holds {} pixels", path.string(),
                                                         image.width_px, image.height_px, image.pixels.size()));
  return {};
}

// The PNG spec write_png writes (pHYs from dpi, straight alpha kept for RGBA).
OIIO::ImageSpec png_spec(const geometry::ImageRgba8& image, int nch, double dpi) {
  OIIO::ImageSpec spec(image.width_px, image.height_px, nch, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  // pHYs: OIIO converts inches to the chunk's pixels per metre; without a unit, only the aspect.
  const float res = dpi > 0 ? static_cast<float>(dpi) : 1.0f;
  spec.attribute("XResolution", res);
  spec.attribute("YResolution", res);
  if (dpi > 0) spec.attribute("ResolutionUnit", "inch");
  // Our pixels carry straight alpha; without this OIIO would un-premultiply them once more.
  if (nch == 4) spec.attribute("oiio:UnassociatedAlpha", 1);
  return spec;
}

}  // namespace

Result<std::string> encode_png(const geometry::ImageRgba8& image, PngChannels channels, double dpi,
                               int compression_level, const std::string& name) {
  if (auto ok = check_size(name, image); !ok) return fail(ok.error());
  const int nch = channels == PngChannels::kRgba ? 4 : 3;
  OIIO::ImageSpec spec = png_spec(image, nch, dpi);
  spec.attribute("png:compressionLevel", std::clamp(compression_level, 0, 9));
  std::vector<std::uint8_t> rgb;
  if (nch == 3) rgb = over_white(image);
  const std::uint8_t* data = nch == 4 ? reinterpret_cast<const std::uint8_t*>(image.pixels.data()) : rgb.data();
  auto out = OIIO::ImageOutput::create("png");
  if (!out || !out->supports("ioproxy"))
    return fail(ErrorCode::kIo, fmt::format("{}: no in-memory PNG writer: {}", name, OIIO::geterror()));
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput vec(bytes);
  out->set_ioproxy(&vec);
  if (!out->open(name, spec)) return fail(ErrorCode::kIo, fmt::format("{}: cannot encode: {}", name, out->geterror()));
  if (!out->write_image(OIIO::TypeDesc::UINT8, data)) {
    std::string why = out->geterror();
    out->close();
    return fail(ErrorCode::kIo, fmt::format("{}: cannot encode image: {}", name, why));
  }
  if (!out->close()) return fail(ErrorCode::kIo, fmt::format("{}: cannot finish image: {}", name, out->geterror()));
  return std::string(bytes.begin(), bytes.end());
}

Status write_jpeg(const std::filesystem::path& path, const geometry::ImageRgba8& image, int quality) {
  if (auto ok = check_size(path, image); !ok) return ok;
  OIIO::ImageSpec spec(image.width_px, image.height_px, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  spec.attribute("Compression", fmt::format("jpeg:{}", std::clamp(quality, 1, 100)));
  return write_whole(path, spec, over_white(image).data());
}

Status write_png(const std::filesystem::path& path, const geometry::ImageRgba8& image, PngChannels channels,
                 double dpi) {
  if (auto ok = check_size(path, image); !ok) return ok;
  const int nch = channels == PngChannels::kRgba ? 4 : 3;
  const OIIO::ImageSpec spec = png_spec(image, nch, dpi);
  if (nch == 4) return write_whole(path, spec, reinterpret_cast<const std::uint8_t*>(image.pixels.data()));
  return write_whole(path, spec, over_white(image).data());
}

Status write_tiff(const std::filesystem::path& path, const ChannelImage8& image, int bits_per_sample,
                  TiffCompression compression) {
  const size_t n =
      static_cast<size_t>(std::max(image.width_px, 0)) * std::max(image.height_px, 0) * image.channel_names.size();
  if (image.samples.size() != n)
    return fail(ErrorCode::kInvalidArgument,
                fmt::format("{}: {}x{}x{} image holds {} samples", path.string(), image.width_px, image.height_px,
                            image.channel_names.size(), image.samples.size()));
  auto w =
      TiffBandWriter::open(path, image.width_px, image.height_px, image.channel_names, bits_per_sample, compression);
  if (!w) return std::unexpected(w.error());
  const auto stride = static_cast<std::ptrdiff_t>(image.width_px * image.channel_names.size());
  if (auto s = (*w)->write_rows(image.height_px, image.samples.data(), stride); !s) return s;
  return (*w)->close();
}

Result<ChannelImage8> read_channels8(const std::filesystem::path& path) {
  const std::string name = path.string();
  OIIO::ImageSpec raw_config;
  raw_config.attribute("oiio:RawColor", 1);  // separated (CMYK) files: the ink samples, not RGB
  auto in = OIIO::ImageInput::open(name, &raw_config);
  if (!in) return fail(ErrorCode::kImage, fmt::format("{}: cannot open image: {}", name, OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 ||
      static_cast<std::int64_t>(spec.width) * spec.height * spec.nchannels > kMaxImagePixels * 4)
    return fail(ErrorCode::kImage,
                fmt::format("{}: unsupported dimensions {}x{}x{}", name, spec.width, spec.height, spec.nchannels));
  ChannelImage8 img;
  img.width_px = spec.width;
  img.height_px = spec.height;
  img.channel_names =
      parse_channel_description(spec.get_string_attribute("ImageDescription"), static_cast<size_t>(spec.nchannels));
  if (img.channel_names.empty()) img.channel_names = spec.channelnames;
  img.samples.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, img.samples.data()))
    return fail(ErrorCode::kImage, fmt::format("{}: cannot decode: {}", name, in->geterror()));
  // n-bit files come back rescaled to 0..255; return the file's own levels.
  const int bits = spec.get_int_attribute("oiio:BitsPerSample", 8);
  if (bits > 0 && bits < 8) {
    const unsigned maxv = (1u << bits) - 1;
    for (auto& s : img.samples) s = static_cast<std::uint8_t>((s * maxv + 127) / 255);
  }
  return img;
}

}  // namespace tp::rip
