// rip/job/separation_output.cpp: interleaves band rows per ink and appends them to separation TIFFs.
#include "rip/job/internal/separation_output.h"

namespace tp::rip {

namespace {

std::filesystem::path per_ink_path(const std::filesystem::path& p, const std::string& ink) {
  return p.parent_path() / (p.stem().string() + "-" + ink + p.extension().string());
}

Status open_set(const std::filesystem::path& path, bool per_ink, const std::vector<std::string>& inks, int width,
                std::int64_t height, int bits, TiffCompression compression,
                std::vector<std::unique_ptr<TiffBandWriter>>& out) {
  if (path.empty()) return {};
  if (!per_ink) {
    auto w = TiffBandWriter::open(path, width, height, inks, bits, compression);
    if (!w) return std::unexpected(w.error());
    out.push_back(std::move(*w));
    return {};
  }
  for (const auto& ink : inks) {
    auto w = TiffBandWriter::open(per_ink_path(path, ink), width, height, {ink}, bits, compression);
    if (!w) return std::unexpected(w.error());
    out.push_back(std::move(*w));
  }
  return {};
}

}  // namespace

Result<std::unique_ptr<SeparationOutput>> SeparationOutput::open(const SeparationFiles& files,
                                                                 const std::vector<std::string>& inks, int width_px,
                                                                 std::int64_t height_px, int bits_per_pixel) {
  auto out = std::make_unique<SeparationOutput>();
  out->width_ = width_px;
  out->channels_ = static_cast<int>(inks.size());
  out->bits_ = bits_per_pixel;
  auto s = open_set(files.contone_tiff, files.one_file_per_ink, inks, width_px, height_px, 8, files.compression,
                    out->contone_);
  if (!s) return std::unexpected(s.error());
  s = open_set(files.screened_tiff, files.one_file_per_ink, inks, width_px, height_px, bits_per_pixel,
               files.compression, out->screened_);
  if (!s) return std::unexpected(s.error());
  return out;
}

Status SeparationOutput::write_band(const BandStage& band, const ScreenedWindow& window, std::int64_t y0, int rows) {
  const int w = width_, nc = channels_;
  // Samples of ink c for pixel x of band row r, into the interleaved layout of writer `set`.
  auto emit = [&](std::vector<std::unique_ptr<TiffBandWriter>>& set, auto&& sample) -> Status {
    if (set.empty()) return {};
    const bool per_ink = set.size() > 1 || nc == 1;
    const int file_channels = per_ink ? 1 : nc;
    rows_.resize(static_cast<size_t>(rows) * w * file_channels);
    for (size_t f = 0; f < set.size(); ++f) {
      for (int r = 0; r < rows; ++r) {
        std::uint8_t* dst = rows_.data() + static_cast<size_t>(r) * w * file_channels;
        for (int c = 0; c < nc; ++c) {
          if (per_ink && c != static_cast<int>(f)) continue;
          const int slot = per_ink ? 0 : c;
          for (int x = 0; x < w; ++x) dst[static_cast<size_t>(x) * file_channels + slot] = sample(r, c, x);
        }
      }
      auto s = set[f]->write_rows(rows, rows_.data(), static_cast<std::ptrdiff_t>(w) * file_channels);
      if (!s) return s;
    }
    return {};
  };
  auto s = emit(contone_, [&](int r, int c, int x) { return band.contone(r, c)[x]; });
  if (!s) return s;
  const int bits = bits_, per_byte = 8 / bits_, mask = (1 << bits_) - 1;
  return emit(screened_, [&](int r, int c, int x) {
    const std::uint8_t byte = window.row(y0 + r, c)[x / per_byte];
    return static_cast<std::uint8_t>((byte >> (8 - bits - (x % per_byte) * bits)) & mask);
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
