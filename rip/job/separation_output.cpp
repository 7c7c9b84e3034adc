// rip/job/separation_output.cpp: interleaves band rows per ink and appends them to separation TIFFs.
#include "rip/job/internal/separation_output.h"

#include <cstring>

namespace tp::rip {

namespace {

std::filesystem::path per_ink_path(const std::filesystem::path& p, const std::string& ink) {
  return p.parent_path() / (p.stem().string() + "-" + ink + p.extension().string());
}

Status open_set(const std::filesystem::path& path, bool per_ink, const std::vector<std::string>& inks, int width,
                std::int64_t height, int bits, TiffCompression compression, double dpi_x, double dpi_y,
                std::vector<std::unique_ptr<TiffBandWriter>>& out) {
  if (path.empty()) return {};
  if (!per_ink) {
    auto w = TiffBandWriter::open(path, width, height, inks, bits, compression, dpi_x, dpi_y);
    if (!w) return std::unexpected(w.error());
    out.push_back(std::move(*w));
    return {};
  }
  for (const auto& ink : inks) {
    auto w = TiffBandWriter::open(per_ink_path(path, ink), width, height, {ink}, bits, compression, dpi_x, dpi_y);
    if (!w) return std::unexpected(w.error());
    out.push_back(std::move(*w));
  }
  return {};
}

}  // namespace

Result<std::unique_ptr<SeparationOutput>> SeparationOutput::open(const SeparationFiles& files,
                                                                 const std::vector<std::string>& inks, int width_px,
                                                                 std::int64_t height_px, int bits_per_pixel,
                                                                 double dpi_x, double dpi_y) {
  auto out = std::make_unique<SeparationOutput>();
  out->width_ = width_px;
  out->channels_ = static_cast<int>(inks.size());
  out->bits_ = bits_per_pixel;
  const int per_byte = 8 / bits_per_pixel, mask = (1 << bits_per_pixel) - 1;
  for (int v = 0; v < 256; ++v)
    for (int k = 0; k < per_byte; ++k)
      out->unpack_[static_cast<size_t>(v)][static_cast<size_t>(k)] =
          static_cast<std::uint8_t>((v >> (8 - bits_per_pixel - k * bits_per_pixel)) & mask);
  auto s = open_set(files.contone_tiff, files.one_file_per_ink, inks, width_px, height_px, 8, files.compression,
                    dpi_x, dpi_y, out->contone_);
  if (!s) return std::unexpected(s.error());
  s = open_set(files.screened_tiff, files.one_file_per_ink, inks, width_px, height_px, bits_per_pixel,
               files.compression, dpi_x, dpi_y, out->screened_);
  if (!s) return std::unexpected(s.error());
  return out;
}

Status SeparationOutput::write_band(ThreadPool& pool, const BandStage& band, const ScreenedWindow& window,
                                    std::int64_t y0, int rows) {
  const int w = width_, nc = channels_;
  const bool per_ink = contone_.size() > 1 || screened_.size() > 1 || nc == 1;
  const int file_channels = per_ink ? 1 : nc;
  // Writes the band to `set`, filling each file's interleaved rows with `fill(r, c, dst, step)`:
  // ink c of band row r into dst[x * step] for every column x. Files are independent: one per
  // thread at a time, each with its own buffer.
  auto emit = [&](std::vector<std::unique_ptr<TiffBandWriter>>& set, auto&& fill) -> Status {
    if (rows_.size() < set.size()) rows_.resize(set.size());
    std::vector<Status> status(set.size());
    pool.parallel_for(static_cast<int>(set.size()), [&](int f, int) {
      std::vector<std::uint8_t>& buf = rows_[static_cast<size_t>(f)];
      buf.resize(static_cast<size_t>(rows) * w * file_channels);
      for (int r = 0; r < rows; ++r) {
        std::uint8_t* dst = buf.data() + static_cast<size_t>(r) * w * file_channels;
        if (per_ink) {
          fill(r, f, dst, 1);
        } else {
          for (int c = 0; c < nc; ++c) fill(r, c, dst + c, nc);
        }
      }
      status[static_cast<size_t>(f)] = set[static_cast<size_t>(f)]->write_rows(rows, buf.data(), static_cast<std::ptrdiff_t>(w) * file_channels);
    });
    for (auto& s : status)
      if (!s) return s;
    return {};
  };
  auto s = emit(contone_, [&](int r, int c, std::uint8_t* dst, int step) {
    const std::uint8_t* src = band.contone(r, c);
    if (step == 1) {
      std::memcpy(dst, src, static_cast<size_t>(w));
      return;
    }
    for (int x = 0; x < w; ++x) dst[static_cast<size_t>(x) * step] = src[x];
  });
  if (!s) return s;
  if (per_ink) {
    // One ink per file: the window's packed rows are the file's rows as they stand.
    std::vector<Status> status(screened_.size());
    pool.parallel_for(static_cast<int>(screened_.size()), [&](int f, int) {
      Status st;
      for (int r = 0; r < rows && st; ++r) st = screened_[static_cast<size_t>(f)]->write_packed_rows(1, window.row(y0 + r, f), 0);
      status[static_cast<size_t>(f)] = st;
    });
    for (auto& st : status)
      if (!st) return st;
    return {};
  }
  // All inks in one file: unpack whole bytes through a table (8 / bits codes per byte).
  const int per_byte = 8 / bits_;
  return emit(screened_, [&](int r, int c, std::uint8_t* dst, int step) {
    const std::uint8_t* src = window.row(y0 + r, c);
    const int full = w / per_byte;
    for (int b = 0; b < full; ++b)
      for (int k = 0; k < per_byte; ++k) dst[(static_cast<size_t>(b) * per_byte + k) * step] = unpack_[src[b]][static_cast<size_t>(k)];
    for (int x = full * per_byte; x < w; ++x) dst[static_cast<size_t>(x) * step] = unpack_[src[full]][static_cast<size_t>(x - full * per_byte)];
  });
}

Status SeparationOutput::close() {
  for (auto* set : {&contone_, &screened_})
    for (auto& w : *set) {
      auto s = w->close();
      if (!s) return s;
    }
  return {};
}

}  // namespace tp::rip
