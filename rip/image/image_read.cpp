// rip/image/image_read.cpp: decodes image files with OpenImageIO and converts them to sRGB RGBA8.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <lcms2.h>
#include <spdlog/fmt/fmt.h>

#include "rip/colour/internal/lcms_handles.h"
#include "rip/common/internal/log.h"
#include "rip/image/image_io.h"
#include "rip/image/internal/orientation.h"

namespace tp::rip {

namespace OIIO = OIIO_NAMESPACE;
using geometry::ImageRgba8;
using geometry::Rgba8;

namespace {

/// Rows decoded per chunk: bounds the temporary 16-bit/float buffers whatever the image height.
constexpr int kChunkRows = 64;

enum class ColourModel { kGrey, kRgb, kCmyk };

int colour_channels(ColourModel m) {
  switch (m) {
    case ColourModel::kGrey: return 1;
    case ColourModel::kRgb: return 3;
    case ColourModel::kCmyk: return 4;
  }
  return 3;
}

/// What the decoder learned from the header.
struct Layout {
  ColourModel model = ColourModel::kRgb;
  int colour_index[4] = {0, 1, 2, 3};  ///< file channel of each colour component
  int alpha_index = -1;
  bool associated_alpha = false;
  bool linear = false;     ///< scene-linear data (EXR): sRGB-encode it
  bool read_float = false;
};

float srgb_encode(float linear) {
  if (!(linear > 0.0f)) return 0.0f;
  if (linear >= 1.0f) return 1.0f;
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::uint16_t to_u16(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return static_cast<std::uint16_t>(std::lround(v * 65535.0f));
}

std::uint8_t u16_to_u8(std::uint32_t v) { return static_cast<std::uint8_t>((v + 128) / 257); }

bool is_linear_colourspace(const std::string& cs) {
  std::string s = cs;
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s == "linear" || s == "lin_srgb" || s == "scene_linear" || s == "lin_rec709";
}

bool names_cmyk(const OIIO::ImageSpec& spec) {
  if (spec.nchannels < 4) return false;
  const char* expect[4] = {"C", "M", "Y", "K"};
  for (int i = 0; i < 4; ++i)
    if (spec.channelnames[i] != expect[i]) return false;
  return true;
}

/// Chooses channels and colour model from the header and the embedded profile (if any).
Result<Layout> plan_layout(const OIIO::ImageSpec& spec, cmsHPROFILE icc, const std::string& name) {
  Layout lay;
  lay.alpha_index = spec.alpha_channel;
  if (lay.alpha_index < 0 && (spec.nchannels == 2 || spec.nchannels == 4) && !names_cmyk(spec))
    lay.alpha_index = spec.nchannels - 1;
  int colour_avail = spec.nchannels - (lay.alpha_index >= 0 ? 1 : 0);
  if (colour_avail < 1) return fail(ErrorCode::kImage, name + ": image has no colour channel");

  // The profile decides the model when it fits the channels; otherwise the channel count does.
  ColourModel by_count = colour_avail >= 4 && names_cmyk(spec) ? ColourModel::kCmyk
                         : colour_avail >= 3                   ? ColourModel::kRgb
                                                               : ColourModel::kGrey;
  lay.model = by_count;
  if (icc) {
    cmsColorSpaceSignature cs = cmsGetColorSpace(icc);
    ColourModel by_icc = cs == cmsSigGrayData ? ColourModel::kGrey
                         : cs == cmsSigRgbData ? ColourModel::kRgb
                         : cs == cmsSigCmykData ? ColourModel::kCmyk
                                                : by_count;
    if (colour_channels(by_icc) <= colour_avail) lay.model = by_icc;
  }
  int k = 0;
  for (int c = 0; c < spec.nchannels && k < colour_channels(lay.model); ++c)
    if (c != lay.alpha_index) lay.colour_index[k++] = c;

  lay.associated_alpha = lay.alpha_index >= 0 && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) == 0;
  lay.read_float = spec.format.is_floating_point();
  lay.linear = lay.read_float || is_linear_colourspace(spec.get_string_attribute("oiio:ColorSpace"));
  if (icc) lay.linear = false;  // the profile describes the encoding itself
  return lay;
}

cmsUInt32Number lcms_input_format(ColourModel m) {
  switch (m) {
    case ColourModel::kGrey: return TYPE_GRAY_16;
    case ColourModel::kRgb: return TYPE_RGB_16;
    case ColourModel::kCmyk: return TYPE_CMYK_16;
  }
  return TYPE_RGB_16;
}

/// Opens the embedded profile, if any. A present but unreadable profile is an error: silently
/// printing with the wrong colours is worse than refusing the image.
Result<lcms::Profile> embedded_profile(const OIIO::ImageSpec& spec, const std::string& name) {
  const OIIO::ParamValue* p = spec.find_attribute("ICCProfile");
  if (!p || p->type().basetype != OIIO::TypeDesc::UINT8 || p->type().numelements() == 0)
    return lcms::Profile{};
  lcms::install_error_handler();
  lcms::Profile prof(cmsOpenProfileFromMem(p->data(), static_cast<cmsUInt32Number>(p->type().numelements())));
  if (!prof) return fail(ErrorCode::kImage, name + ": embedded ICC profile is unreadable");
  return prof;
}

/// Converts one chunk of decoded rows (16-bit colour planes + alpha) into RGBA8 output rows.
class ChunkConverter {
 public:
  ChunkConverter(const Layout& lay, void* transform) : lay_(lay), transform_(transform) {}

  void convert(const std::uint16_t* colour, const std::uint16_t* alpha, int pixels, Rgba8* out) {
    const int nc = colour_channels(lay_.model);
    if (transform_) {
      rgb_.resize(static_cast<size_t>(pixels) * 3);
      cmsDoTransform(transform_, colour, rgb_.data(), static_cast<cmsUInt32Number>(pixels));
      for (int i = 0; i < pixels; ++i)
        out[i] = {u16_to_u8(rgb_[3 * i]), u16_to_u8(rgb_[3 * i + 1]), u16_to_u8(rgb_[3 * i + 2]), 255};
    } else if (lay_.model == ColourModel::kGrey) {
      for (int i = 0; i < pixels; ++i) {
        std::uint8_t g = u16_to_u8(colour[i]);
        out[i] = {g, g, g, 255};
      }
    } else if (lay_.model == ColourModel::kRgb) {
      for (int i = 0; i < pixels; ++i)
        out[i] = {u16_to_u8(colour[3 * i]), u16_to_u8(colour[3 * i + 1]), u16_to_u8(colour[3 * i + 2]), 255};
    } else {
      // CMYK without a profile: the textbook complement, the best guess without colorimetry.
      for (int i = 0; i < pixels; ++i) {
        const std::uint16_t* c = colour + static_cast<size_t>(nc) * i;
        auto ch = [&](int j) {
          std::uint32_t v = (65535u - c[j]) * (65535u - c[3]) / 65535u;
          return u16_to_u8(v);
        };
        out[i] = {ch(0), ch(1), ch(2), 255};
      }
    }
    if (alpha)
      for (int i = 0; i < pixels; ++i) out[i].a = u16_to_u8(alpha[i]);
  }

 private:
  const Layout& lay_;
  void* transform_;
  std::vector<std::uint16_t> rgb_;
};

/// The byte-wide path: 8-bit grey or RGB (+ straight alpha), optionally through an 8-bit transform.
Status decode8(OIIO::ImageInput& in, const Layout& lay, void* transform, const std::string& name, ImageRgba8& img) {
  const OIIO::ImageSpec& spec = in.spec();
  const int nch = spec.nchannels, w = spec.width;
  const bool grey = lay.model == ColourModel::kGrey;
  std::vector<std::uint8_t> raw(static_cast<size_t>(w) * kChunkRows * nch);
  std::vector<std::uint8_t> colour(static_cast<size_t>(w) * kChunkRows * 3), rgb(colour.size());
  for (int y0 = 0; y0 < spec.height; y0 += kChunkRows) {
    const int rows = std::min(kChunkRows, spec.height - y0);
    const size_t px = static_cast<size_t>(rows) * w;
    if (!in.read_scanlines(0, 0, y0 + spec.y, y0 + spec.y + rows, 0, 0, nch, OIIO::TypeDesc::UINT8, raw.data()))
      return fail(ErrorCode::kImage,
                  fmt::format("{}: cannot decode rows {}..{}: {}", name, y0, y0 + rows - 1, in.geterror()));
    Rgba8* out = img.pixels.data() + static_cast<size_t>(y0) * w;
    const int ci0 = lay.colour_index[0], ci1 = lay.colour_index[1], ci2 = lay.colour_index[2];
    if (transform) {
      // Gather the colour channels contiguously for lcms2, convert, then add alpha.
      const int nc = grey ? 1 : 3;
      for (size_t i = 0; i < px; ++i)
        for (int c = 0; c < nc; ++c) colour[i * nc + c] = raw[i * nch + lay.colour_index[c]];
      cmsDoTransform(transform, colour.data(), rgb.data(), static_cast<cmsUInt32Number>(px));
      for (size_t i = 0; i < px; ++i) out[i] = {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], 255};
    } else if (grey) {
      for (size_t i = 0; i < px; ++i) {
        const std::uint8_t g = raw[i * nch + ci0];
        out[i] = {g, g, g, 255};
      }
    } else {
      for (size_t i = 0; i < px; ++i) {
        const std::uint8_t* p = raw.data() + i * nch;
        out[i] = {p[ci0], p[ci1], p[ci2], 255};
      }
    }
    if (lay.alpha_index >= 0)
      for (size_t i = 0; i < px; ++i) out[i].a = raw[i * nch + lay.alpha_index];
  }
  return {};
}

Result<ImageRgba8> decode(OIIO::ImageInput& in, const std::string& name) {
  const OIIO::ImageSpec spec = in.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0)
    return fail(ErrorCode::kImage, fmt::format("{}: invalid dimensions {}x{}x{} with {} channels", name,
                                               spec.width, spec.height, spec.depth, spec.nchannels));
  if (static_cast<std::int64_t>(spec.width) * spec.height > kMaxImagePixels)
    return fail(ErrorCode::kImage, fmt::format("{}: {}x{} pixels exceeds the limit of {} pixels", name,
                                               spec.width, spec.height, kMaxImagePixels));

  auto prof = embedded_profile(spec, name);
  if (!prof) return std::unexpected(prof.error());
  auto lay_r = plan_layout(spec, prof->get(), name);
  if (!lay_r) return std::unexpected(lay_r.error());
  const Layout lay = *lay_r;

  // 8-bit files without premultiplied alpha take a byte-wide path (JPEG and most PNG/TIFF designs).
  const bool fast8 = spec.format == OIIO::TypeDesc::UINT8 && !lay.read_float && !lay.linear && !lay.associated_alpha &&
                     lay.model != ColourModel::kCmyk;
  lcms::Transform xform;
  if (*prof) {
    cmsColorSpaceSignature cs = cmsGetColorSpace(prof->get());
    bool fits = (cs == cmsSigGrayData && lay.model == ColourModel::kGrey) ||
                (cs == cmsSigRgbData && lay.model == ColourModel::kRgb) ||
                (cs == cmsSigCmykData && lay.model == ColourModel::kCmyk);
    if (!fits) {
      logger().warn("{}: embedded ICC profile does not match its {} colour channels; taken as sRGB", name,
                    colour_channels(lay.model));
    } else {
      lcms::Profile srgb(cmsCreate_sRGBProfile());
      const cmsUInt32Number in_fmt = fast8 ? (lay.model == ColourModel::kGrey ? TYPE_GRAY_8 : TYPE_RGB_8)
                                           : lcms_input_format(lay.model);
      xform.reset(cmsCreateTransform(prof->get(), in_fmt, srgb.get(), fast8 ? TYPE_RGB_8 : TYPE_RGB_16,
                                     INTENT_RELATIVE_COLORIMETRIC, cmsFLAGS_BLACKPOINTCOMPENSATION));
      if (!xform) return fail(ErrorCode::kImage, name + ": embedded ICC profile cannot convert to sRGB");
    }
  }

  ImageRgba8 img;
  img.width_px = spec.width;
  img.height_px = spec.height;
  img.source = name;
  img.pixels.resize(static_cast<size_t>(spec.width) * spec.height);

  if (fast8) {
    auto ok = decode8(in, lay, xform.get(), name, img);
    if (!ok) return std::unexpected(ok.error());
    return apply_exif_orientation(std::move(img), spec.get_int_attribute("Orientation", 1));
  }
  const int nch = spec.nchannels, nc = colour_channels(lay.model);
  const size_t row_vals = static_cast<size_t>(spec.width) * nch;
  std::vector<std::uint16_t> raw16;
  std::vector<float> rawf;
  std::vector<std::uint16_t> colour(static_cast<size_t>(spec.width) * kChunkRows * nc);
  std::vector<std::uint16_t> alpha(lay.alpha_index >= 0 ? static_cast<size_t>(spec.width) * kChunkRows : 0);
  ChunkConverter conv(lay, xform.get());
  const bool use_float = lay.read_float || lay.linear;

  // Decode a chunk of rows at a time so temporary buffers stay small for huge images.
  for (int y0 = 0; y0 < spec.height; y0 += kChunkRows) {
    const int rows = std::min(kChunkRows, spec.height - y0);
    const size_t px = static_cast<size_t>(rows) * spec.width;
    bool ok;
    if (use_float) {
      rawf.resize(row_vals * rows);
      ok = in.read_scanlines(0, 0, y0 + spec.y, y0 + spec.y + rows, 0, 0, nch, OIIO::TypeDesc::FLOAT,
                             rawf.data());
    } else {
      raw16.resize(row_vals * rows);
      ok = in.read_scanlines(0, 0, y0 + spec.y, y0 + spec.y + rows, 0, 0, nch, OIIO::TypeDesc::UINT16,
                             raw16.data());
    }
    if (!ok)
      return fail(ErrorCode::kImage,
                  fmt::format("{}: cannot decode rows {}..{}: {}", name, y0, y0 + rows - 1, in.geterror()));

    for (size_t i = 0; i < px; ++i) {
      if (use_float) {
        const float* p = rawf.data() + i * nch;
        float a = lay.alpha_index >= 0 ? std::clamp(p[lay.alpha_index], 0.0f, 1.0f) : 1.0f;
        float inv = lay.associated_alpha && a > 0 ? 1.0f / a : 1.0f;
        for (int c = 0; c < nc; ++c) {
          float v = p[lay.colour_index[c]] * inv;
          colour[i * nc + c] = to_u16(lay.linear ? srgb_encode(v) : v);
        }
        if (!alpha.empty()) alpha[i] = to_u16(a);
      } else {
        const std::uint16_t* p = raw16.data() + i * nch;
        std::uint32_t a = lay.alpha_index >= 0 ? p[lay.alpha_index] : 65535u;
        for (int c = 0; c < nc; ++c) {
          std::uint32_t v = p[lay.colour_index[c]];
          if (lay.associated_alpha) v = a ? std::min<std::uint32_t>(65535u, (v * 65535u + a / 2) / a) : 0;
          colour[i * nc + c] = static_cast<std::uint16_t>(v);
        }
        if (!alpha.empty()) alpha[i] = static_cast<std::uint16_t>(a);
      }
    }
    conv.convert(colour.data(), alpha.empty() ? nullptr : alpha.data(), static_cast<int>(px),
                 img.pixels.data() + static_cast<size_t>(y0) * spec.width);
  }
  return apply_exif_orientation(std::move(img), spec.get_int_attribute("Orientation", 1));
}

Result<ImageRgba8> open_and_decode(const std::string& name, OIIO::Filesystem::IOProxy* proxy) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  // OIIO 2.4 readers look for the proxy in the configuration hints as well as in the argument.
  if (proxy) config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto in = OIIO::ImageInput::open(name, &config, proxy);
  if (!in) {
    std::string why = OIIO::geterror();
    return fail(ErrorCode::kImage, fmt::format("{}: cannot open image: {}", name, why.empty() ? "unknown format" : why));
  }
  auto result = decode(*in, name);
  in->close();
  return result;
}

}  // namespace

Result<ImageRgba8> read_image(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return fail(ErrorCode::kImage, path.string() + ": no such image file");
  return open_and_decode(path.string(), nullptr);
}

Result<ImageRgba8> read_image_from_memory(std::span<const std::uint8_t> bytes, std::string_view name) {
  OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
  return open_and_decode(std::string(name), &proxy);
}

}  // namespace tp::rip
