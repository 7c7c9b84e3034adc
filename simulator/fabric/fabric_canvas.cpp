// simulator/fabric/fabric_canvas.cpp: laying drops, spilling finished rows, writing TIFF and PNG.
#include "simulator/fabric/fabric_canvas.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "device/swath/packbits.h"
#include "simulator/fabric/fabric_preview.h"
#include "simulator/fabric/fabric_tiff.h"

namespace tp::sim {

Result<std::unique_ptr<FabricCanvas>> FabricCanvas::create(FabricSpec spec, const std::filesystem::path& scratch) {
  if (spec.width_px == 0 || spec.inks.empty())
    return fail(ErrorCode::kInvalidArgument, "fabric: width and inks must be non-zero");
  spec.look.inks = spec.inks;
  auto colour = FabricColourModel::create(spec.look, spec.bits_per_pixel);
  if (!colour) return fail(colour.error().with_context("fabric"));
  std::FILE* f = std::fopen(scratch.c_str(), "w+b");
  if (!f) return fail(ErrorCode::kOutput, scratch.string() + ": cannot create the fabric scratch file");
  return std::unique_ptr<FabricCanvas>(new FabricCanvas(std::move(spec), std::move(*colour), f, scratch));
}

FabricCanvas::FabricCanvas(FabricSpec spec, FabricColourModel colour, std::FILE* scratch,
                           std::filesystem::path scratch_path)
    : spec_(std::move(spec)),
      colour_(std::move(colour)),
      row_bytes_(static_cast<std::size_t>(spec_.width_px) * spec_.inks.size()),
      scratch_(scratch),
      scratch_path_(std::move(scratch_path)) {
  summary_.width_px = spec_.width_px;
}

FabricCanvas::~FabricCanvas() {
  if (scratch_) std::fclose(scratch_);
  std::error_code ec;
  std::filesystem::remove(scratch_path_, ec);
}

std::vector<std::uint8_t>& FabricCanvas::row(std::int64_t r) {
  while (base_row_ + static_cast<std::int64_t>(window_.size()) <= r) window_.emplace_back(row_bytes_, 0);
  summary_.peak_window_rows = std::max<std::uint64_t>(summary_.peak_window_rows, window_.size());
  return window_[static_cast<std::size_t>(r - base_row_)];
}

void FabricCanvas::spill_until(std::int64_t r) {
  std::vector<std::uint8_t> packed;
  while (base_row_ < r) {
    std::uint32_t len = 0;
    packed.clear();
    if (!window_.empty()) {
      const auto& front = window_.front();
      // Blank rows (most of a marker's margins) cost four bytes.
      if (std::any_of(front.begin(), front.end(), [](std::uint8_t v) { return v != 0; })) {
        device::packbits_encode(front, packed);
        len = static_cast<std::uint32_t>(packed.size());
      }
      window_.pop_front();
    }
    std::fwrite(&len, sizeof len, 1, scratch_);
    if (len) std::fwrite(packed.data(), 1, packed.size(), scratch_);
    ++base_row_;
    ++spilled_rows_;
  }
}

void FabricCanvas::lay(const device::SwathHeader& h, std::span<const std::uint8_t> raw, std::int64_t fabric_row) {
  if (fabric_row - spec_.reach_rows > base_row_) spill_until(fabric_row - spec_.reach_rows);
  const std::size_t rb = device::swath_row_bytes(h);
  const int bpp = h.bits_per_pixel;
  const unsigned mask = (1u << bpp) - 1;
  const std::size_t nch = std::min<std::size_t>(h.channels, spec_.inks.size());
  const std::size_t stride = spec_.inks.size();
  for (std::uint32_t i = 0; i < h.rows; ++i) {
    const std::int64_t fr = fabric_row + static_cast<std::int64_t>(i) * h.row_step;
    if (fr < base_row_) {
      ++summary_.late_rows;
      continue;
    }
    std::vector<std::uint8_t>& dst = row(fr);
    for (std::size_t c = 0; c < nch; ++c) {
      const std::uint8_t* src = raw.data() + (c * h.rows + i) * rb;
      // Walk whole bytes: blank bytes (most of a marker) cost one test for 8 / bpp pixels.
      const std::uint32_t per_byte = 8 / bpp;
      for (std::size_t byte = 0; byte < rb; ++byte) {
        const std::uint8_t b = src[byte];
        if (!b) continue;
        for (std::uint32_t k = 0; k < per_byte; ++k) {
          const unsigned level = (b >> (8 - bpp * (k + 1))) & mask;
          const std::uint32_t px = static_cast<std::uint32_t>(byte) * per_byte + k;
          if (!level || px >= h.width_px) continue;
          const std::int64_t x = h.x_start_px + static_cast<std::int64_t>(px);
          if (x < 0 || x >= static_cast<std::int64_t>(spec_.width_px)) {
            ++summary_.clipped_pixels;
            continue;
          }
          // Files hold the roll frame: column = roll x, whichever side the carriage starts.
          const std::int64_t col = spec_.columns_reversed ? static_cast<std::int64_t>(spec_.width_px) - 1 - x : x;
          std::uint8_t& v = dst[static_cast<std::size_t>(col) * stride + c];
          v = static_cast<std::uint8_t>(std::min(255u, v + level));
        }
      }
    }
  }
}

Result<FabricSummary> FabricCanvas::finish(const std::filesystem::path& tif, const std::filesystem::path& png,
                                           std::uint32_t preview_max_width) {
  spill_until(base_row_ + static_cast<std::int64_t>(window_.size()));
  std::fflush(scratch_);
  const std::uint64_t height = std::max<std::uint64_t>(1, spilled_rows_);
  summary_.height_px = height;
  const int scale = static_cast<int>(std::max<std::uint32_t>(1, (spec_.width_px + preview_max_width - 1) / preview_max_width));
  summary_.preview_scale = scale;

  auto tout = FabricTiff::open(tif, spec_.width_px, height, spec_.inks, spec_.dpi_x, spec_.dpi_y);
  if (!tout) return std::unexpected(tout.error());

  PreviewSpec pv{spec_.width_px, height, scale, spec_.dpi_x, spec_.dpi_y};
  auto preview = FabricPreview::open(colour_, pv, png,
                                     spec_.lab_file_name.empty() ? std::filesystem::path{} : png.parent_path() / spec_.lab_file_name);
  if (!preview) return fail(preview.error());

  std::vector<std::uint8_t> line(row_bytes_), packed;
  std::rewind(scratch_);
  for (std::uint64_t y = 0; y < height; ++y) {
    std::uint32_t len = 0;
    if (y < spilled_rows_ && std::fread(&len, sizeof len, 1, scratch_) != 1)
      return fail(ErrorCode::kOutput, scratch_path_.string() + ": fabric scratch truncated at row " + std::to_string(y));
    if (len == 0) {
      std::fill(line.begin(), line.end(), 0);
    } else {
      packed.resize(len);
      line.clear();
      if (std::fread(packed.data(), 1, len, scratch_) != len || !device::packbits_decode(packed, row_bytes_, line))
        return fail(ErrorCode::kOutput, scratch_path_.string() + ": fabric scratch corrupt at row " + std::to_string(y));
    }
    if (auto w = (*tout)->write_row(line.data()); !w) return std::unexpected(w.error());
    if (auto st = (*preview)->add_row(line); !st) return fail(st.error());
  }
  if (auto c = (*tout)->close(); !c) return std::unexpected(c.error());
  if (auto st = (*preview)->close(); !st) return fail(st.error());
  return summary_;
}

}  // namespace tp::sim
