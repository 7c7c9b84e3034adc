// rip/image/tiff_band_writer.cpp: scanline-order TIFF output through OpenImageIO.
#include "rip/image/tiff_band_writer.h"

#include <algorithm>

#include <OpenImageIO/imageio.h>
#include <spdlog/fmt/fmt.h>

#include "rip/image/internal/tiff_spec.h"

namespace tp::rip {

namespace OIIO = OIIO_NAMESPACE;

struct TiffBandWriter::Impl {
  std::string name;
  std::unique_ptr<OIIO::ImageOutput> out;
  int width = 0, channels = 0, bits = 8;
  std::int64_t height = 0, next_row = 0;
  std::vector<std::uint8_t> scaled;
  bool closed = false;
};

TiffBandWriter::TiffBandWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

TiffBandWriter::~TiffBandWriter() {
  if (impl_ && !impl_->closed && impl_->out) impl_->out->close();
}

Result<std::unique_ptr<TiffBandWriter>> TiffBandWriter::open(const std::filesystem::path& path, int width_px,
                                                             std::int64_t height_px,
                                                             const std::vector<std::string>& channel_names,
                                                             int bits_per_sample, TiffCompression compression) {
  if (height_px > (std::int64_t{1} << 31) - 1)
    return fail(ErrorCode::kInvalidArgument, fmt::format("{}: {} rows is too tall for TIFF", path.string(), height_px));
  auto spec = tiff_spec(path, width_px, static_cast<int>(height_px), channel_names, bits_per_sample, compression);
  if (!spec) return std::unexpected(spec.error());
  auto impl = std::make_unique<Impl>();
  impl->name = path.string();
  impl->out = OIIO::ImageOutput::create(impl->name);
  if (!impl->out)
    return fail(ErrorCode::kIo, fmt::format("{}: cannot create TIFF writer: {}", impl->name, OIIO::geterror()));
  if (!impl->out->open(impl->name, *spec))
    return fail(ErrorCode::kIo, fmt::format("{}: cannot open for writing: {}", impl->name, impl->out->geterror()));
  impl->width = width_px;
  impl->height = height_px;
  impl->channels = static_cast<int>(channel_names.size());
  impl->bits = bits_per_sample;
  return std::unique_ptr<TiffBandWriter>(new TiffBandWriter(std::move(impl)));
}

Status TiffBandWriter::write_rows(int rows, const std::uint8_t* samples, std::ptrdiff_t row_stride_bytes) {
  Impl& m = *impl_;
  if (m.closed || rows < 0 || m.next_row + rows > m.height)
    return fail(ErrorCode::kIo, fmt::format("{}: rows {}..{} outside the image's {} rows", m.name, m.next_row,
                                            m.next_row + rows - 1, m.height));
  const std::uint8_t* data = samples;
  std::ptrdiff_t stride = row_stride_bytes;
  if (m.bits < 8) {
    // OIIO rescales 8-bit samples to the file's bit depth: hand it full-range values.
    const size_t row_len = static_cast<size_t>(m.width) * m.channels;
    const unsigned maxv = (1u << m.bits) - 1;
    m.scaled.resize(row_len * rows);
    for (int r = 0; r < rows; ++r) {
      const std::uint8_t* src = samples + r * row_stride_bytes;
      std::uint8_t* dst = m.scaled.data() + r * row_len;
      for (size_t i = 0; i < row_len; ++i) dst[i] = static_cast<std::uint8_t>(std::min<unsigned>(src[i], maxv) * 255 / maxv);
    }
    data = m.scaled.data();
    stride = static_cast<std::ptrdiff_t>(row_len);
  }
  const int y0 = static_cast<int>(m.next_row);
  if (!m.out->write_scanlines(y0, y0 + rows, 0, OIIO::TypeDesc::UINT8, data, OIIO::AutoStride, stride))
    return fail(ErrorCode::kIo, fmt::format("{}: cannot write rows {}..{}: {}", m.name, y0, y0 + rows - 1,
                                            m.out->geterror()));
  m.next_row += rows;
  return {};
}

Status TiffBandWriter::close() {
  Impl& m = *impl_;
  if (m.closed) return {};
  m.closed = true;
  if (m.next_row != m.height) {
    m.out->close();
    return fail(ErrorCode::kIo, fmt::format("{}: closed after {} of {} rows", m.name, m.next_row, m.height));
  }
  if (!m.out->close()) return fail(ErrorCode::kIo, fmt::format("{}: cannot finish TIFF: {}", m.name, m.out->geterror()));
  return {};
}

}  // namespace tp::rip
