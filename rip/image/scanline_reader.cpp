// rip/image/scanline_reader.cpp: image decoding with OpenImageIO, channel layout, alpha, and conversion
// of embedded ICC profiles to sRGB with lcms2, a chunk of rows at a time.
#include "rip/image/internal/scanline_reader.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <lcms2.h>
#include <spdlog/fmt/fmt.h>

#include "geometry/common/srgb.h"
#include "rip/colour/internal/lcms_handles.h"
#include "rip/common/internal/log.h"
#include "rip/image/internal/preflight.h"

namespace tp::rip {

namespace OIIO = OIIO_NAMESPACE;
using geometry::Rgba8;

namespace {

/// Widest image accepted (a 1.7 m roll at 15 000 dpi): a guard against hostile headers.
constexpr int kMaxWidthPx = 1 << 20;

/// Decoded bytes per chunk of rows: bounds the temporary 16-bit/float buffers whatever the image
/// height, while narrow images still decode in few calls (each call costs a decoder seek and setup).
constexpr std::size_t kChunkBytes = std::size_t{8} << 20;
/// Widest decoded row accepted (2^20 pixels of 16 float channels): a guard against hostile headers.
constexpr std::size_t kMaxRowBytes = std::size_t{64} << 20;

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

}  // namespace

struct ScanlineReader::Impl {
  std::string name;
  std::unique_ptr<OIIO::ImageInput> in;
  OIIO::ImageSpec spec;
  Layout lay;
  lcms::Profile profile;
  lcms::Transform transform;
  bool fast8 = false;   ///< 8-bit file decoded byte-wide
  bool use_float = false;
  int next_row = 0;
  int chunk_rows = 1;  ///< rows decoded per call
  std::vector<std::uint8_t> raw8, colour8, rgb8;
  std::vector<std::uint16_t> raw16, colour16, alpha16;
  std::vector<float> rawf;
  std::unique_ptr<ChunkConverter> conv;

  /// The byte-wide path: 8-bit grey or RGB (+ straight alpha), optionally through an 8-bit transform.
  void convert8(int pixels, Rgba8* out) {
    const int nch = spec.nchannels;
    const bool grey = lay.model == ColourModel::kGrey;
    const int ci0 = lay.colour_index[0], ci1 = lay.colour_index[1], ci2 = lay.colour_index[2];
    if (transform) {
      // Gather the colour channels contiguously for lcms2, convert, then add alpha.
      const int nc = grey ? 1 : 3;
      for (int i = 0; i < pixels; ++i)
        for (int c = 0; c < nc; ++c) colour8[static_cast<size_t>(i) * nc + c] = raw8[static_cast<size_t>(i) * nch + lay.colour_index[c]];
      cmsDoTransform(transform.get(), colour8.data(), rgb8.data(), static_cast<cmsUInt32Number>(pixels));
      for (int i = 0; i < pixels; ++i) out[i] = {rgb8[3 * i], rgb8[3 * i + 1], rgb8[3 * i + 2], 255};
    } else if (grey) {
      for (int i = 0; i < pixels; ++i) {
        const std::uint8_t g = raw8[static_cast<size_t>(i) * nch + ci0];
        out[i] = {g, g, g, 255};
      }
    } else {
      for (int i = 0; i < pixels; ++i) {
        const std::uint8_t* p = raw8.data() + static_cast<size_t>(i) * nch;
        out[i] = {p[ci0], p[ci1], p[ci2], 255};
      }
    }
    if (lay.alpha_index >= 0)
      for (int i = 0; i < pixels; ++i) out[i].a = raw8[static_cast<size_t>(i) * nch + lay.alpha_index];
  }

  /// The wide path: 16-bit or float samples, premultiplied alpha, linear data, CMYK.
  void convert_wide(int pixels, Rgba8* out) {
    const int nch = spec.nchannels, nc = colour_channels(lay.model);
    for (int i = 0; i < pixels; ++i) {
      if (use_float) {
        const float* p = rawf.data() + static_cast<size_t>(i) * nch;
        const float a = lay.alpha_index >= 0 ? std::clamp(p[lay.alpha_index], 0.0f, 1.0f) : 1.0f;
        const float inv = lay.associated_alpha && a > 0 ? 1.0f / a : 1.0f;
        for (int c = 0; c < nc; ++c) {
          const float v = p[lay.colour_index[c]] * inv;
          colour16[static_cast<size_t>(i) * nc + c] = to_u16(lay.linear ? linear_to_srgb(v) : v);
        }
        if (!alpha16.empty()) alpha16[static_cast<size_t>(i)] = to_u16(a);
      } else {
        const std::uint16_t* p = raw16.data() + static_cast<size_t>(i) * nch;
        const std::uint32_t a = lay.alpha_index >= 0 ? p[lay.alpha_index] : 65535u;
        for (int c = 0; c < nc; ++c) {
          std::uint32_t v = p[lay.colour_index[c]];
          if (lay.associated_alpha) v = a ? std::min<std::uint32_t>(65535u, (v * 65535u + a / 2) / a) : 0;
          colour16[static_cast<size_t>(i) * nc + c] = static_cast<std::uint16_t>(v);
        }
        if (!alpha16.empty()) alpha16[static_cast<size_t>(i)] = static_cast<std::uint16_t>(a);
      }
    }
    conv->convert(colour16.data(), alpha16.empty() ? nullptr : alpha16.data(), pixels, out);
  }
};

ScanlineReader::ScanlineReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ScanlineReader::~ScanlineReader() {
  if (impl_ && impl_->in) impl_->in->close();
}

int ScanlineReader::width_px() const { return impl_->spec.width; }
int ScanlineReader::height_px() const { return impl_->spec.height; }
int ScanlineReader::orientation() const { return impl_->spec.get_int_attribute("Orientation", 1); }
int ScanlineReader::next_row() const { return impl_->next_row; }

Result<std::unique_ptr<ScanlineReader>> ScanlineReader::open(const std::string& name, OIIO::Filesystem::IOProxy* proxy) {
  auto m = std::make_unique<Impl>();
  m->name = name;
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  // OIIO 2.4 readers look for the proxy in the configuration hints as well as in the argument.
  if (proxy) config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  // The container is checked first and the reader chosen by content, so OpenImageIO never falls
  // back to trying its other format plugins on a file its own reader refused (see preflight.h).
  Result<ImageFormat> format = [&]() -> Result<ImageFormat> {
    if (proxy) return preflight_image(name, *proxy);
    OIIO::Filesystem::IOFile file(name, OIIO::Filesystem::IOProxy::Read);
    if (!file.opened()) return fail(ErrorCode::kImage, name + ": cannot open image file");
    return preflight_image(name, file);
  }();
  if (!format) return std::unexpected(format.error());
  m->in = OIIO::ImageInput::create(oiio_format_name(*format), false, &config, proxy);
  if (m->in && proxy && !m->in->set_ioproxy(proxy)) m->in.reset();
  if (!m->in) {
    std::string why = OIIO::geterror();
    return fail(ErrorCode::kImage, fmt::format("{}: no {} reader: {}", name, oiio_format_name(*format), why));
  }
  OIIO::ImageSpec opened;
  if (!m->in->open(name, opened, config)) {
    std::string why = m->in->geterror();
    if (why.empty()) why = OIIO::geterror();
    m->in.reset();
    return fail(ErrorCode::kImage, fmt::format("{}: cannot open image: {}", name, why.empty() ? "corrupt file" : why));
  }
  m->spec = m->in->spec();
  const OIIO::ImageSpec& spec = m->spec;
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0 || spec.nchannels > 64 ||
      spec.width > kMaxWidthPx)
    return fail(ErrorCode::kImage, fmt::format("{}: unsupported dimensions {}x{}x{} with {} channels", name, spec.width,
                                               spec.height, spec.depth, spec.nchannels));
  auto prof = embedded_profile(spec, name);
  if (!prof) return std::unexpected(prof.error());
  m->profile = std::move(*prof);
  auto lay = plan_layout(spec, m->profile.get(), name);
  if (!lay) return std::unexpected(lay.error());
  m->lay = *lay;
  m->use_float = m->lay.read_float || m->lay.linear;
  // 8-bit files without premultiplied alpha take a byte-wide path (JPEG and most PNG/TIFF designs).
  m->fast8 = spec.format == OIIO::TypeDesc::UINT8 && !m->use_float && !m->lay.associated_alpha &&
             m->lay.model != ColourModel::kCmyk;
  if (m->profile) {
    const cmsColorSpaceSignature cs = cmsGetColorSpace(m->profile.get());
    const bool fits = (cs == cmsSigGrayData && m->lay.model == ColourModel::kGrey) ||
                      (cs == cmsSigRgbData && m->lay.model == ColourModel::kRgb) ||
                      (cs == cmsSigCmykData && m->lay.model == ColourModel::kCmyk);
    if (!fits) {
      logger().warn("{}: embedded ICC profile does not match its {} colour channels; taken as sRGB", name,
                    colour_channels(m->lay.model));
    } else {
      lcms::Profile srgb(cmsCreate_sRGBProfile());
      const cmsUInt32Number in_fmt = m->fast8 ? (m->lay.model == ColourModel::kGrey ? TYPE_GRAY_8 : TYPE_RGB_8)
                                              : lcms_input_format(m->lay.model);
      m->transform.reset(cmsCreateTransform(m->profile.get(), in_fmt, srgb.get(), m->fast8 ? TYPE_RGB_8 : TYPE_RGB_16,
                                            INTENT_RELATIVE_COLORIMETRIC, cmsFLAGS_BLACKPOINTCOMPENSATION));
      if (!m->transform) return fail(ErrorCode::kImage, name + ": embedded ICC profile cannot convert to sRGB");
    }
  }
  const std::size_t row_bytes = static_cast<std::size_t>(spec.width) * spec.nchannels * (m->use_float ? 4 : 2);
  if (row_bytes > kMaxRowBytes)
    return fail(ErrorCode::kImage, fmt::format("{}: a row of {} pixels x {} channels exceeds {} MiB decoded", name,
                                               spec.width, spec.nchannels, kMaxRowBytes >> 20));
  m->chunk_rows = static_cast<int>(std::clamp<std::size_t>(kChunkBytes / row_bytes, 1, spec.height));
  const size_t chunk_px = static_cast<size_t>(spec.width) * m->chunk_rows;
  const int nc = colour_channels(m->lay.model);
  if (m->fast8) {
    m->raw8.resize(chunk_px * spec.nchannels);
    if (m->transform) {
      m->colour8.resize(chunk_px * 3);
      m->rgb8.resize(chunk_px * 3);
    }
  } else {
    if (m->use_float) m->rawf.resize(chunk_px * spec.nchannels);
    else m->raw16.resize(chunk_px * spec.nchannels);
    m->colour16.resize(chunk_px * nc);
    if (m->lay.alpha_index >= 0) m->alpha16.resize(chunk_px);
    m->conv = std::make_unique<ChunkConverter>(m->lay, m->transform.get());
  }
  return std::unique_ptr<ScanlineReader>(new ScanlineReader(std::move(m)));
}

Status ScanlineReader::read_rows(int rows, Rgba8* out, std::ptrdiff_t stride_px) {
  Impl& m = *impl_;
  const OIIO::ImageSpec& spec = m.spec;
  if (rows < 0 || m.next_row + rows > spec.height)
    return fail(ErrorCode::kImage, fmt::format("{}: rows {}..{} past the image's {} rows", m.name, m.next_row,
                                               m.next_row + rows - 1, spec.height));
  const int nch = spec.nchannels, w = spec.width;
  // Decode a chunk of rows at a time so temporary buffers stay small whatever the image height.
  for (int done = 0; done < rows;) {
    const int n = std::min(m.chunk_rows, rows - done);
    const int y0 = m.next_row;
    const OIIO::TypeDesc type = m.fast8 ? OIIO::TypeDesc::UINT8 : m.use_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT16;
    void* raw = m.fast8 ? static_cast<void*>(m.raw8.data()) : m.use_float ? static_cast<void*>(m.rawf.data())
                                                                           : static_cast<void*>(m.raw16.data());
    if (!m.in->read_scanlines(0, 0, y0 + spec.y, y0 + spec.y + n, 0, 0, nch, type, raw))
      return fail(ErrorCode::kImage, fmt::format("{}: cannot decode rows {}..{}: {}", m.name, y0, y0 + n - 1, m.in->geterror()));
    // Converted straight into `out` when its rows are contiguous, else through a chunk buffer.
    if (stride_px == w) {
      if (m.fast8) m.convert8(n * w, out + static_cast<std::ptrdiff_t>(done) * stride_px);
      else m.convert_wide(n * w, out + static_cast<std::ptrdiff_t>(done) * stride_px);
    } else {
      std::vector<Rgba8> tmp(static_cast<size_t>(n) * w);
      if (m.fast8) m.convert8(n * w, tmp.data());
      else m.convert_wide(n * w, tmp.data());
      for (int r = 0; r < n; ++r)
        std::copy_n(tmp.data() + static_cast<size_t>(r) * w, w, out + static_cast<std::ptrdiff_t>(done + r) * stride_px);
    }
    m.next_row += n;
    done += n;
  }
  return {};
}

}  // namespace tp::rip
