// simulator/fabric/fabric_preview.cpp: mean pixel colour per preview pixel and the two colour files.
#include "simulator/fabric/fabric_preview.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

namespace tp::sim {

struct FabricPreview::Files {
  std::unique_ptr<OIIO::ImageOutput> png, lab;
  std::filesystem::path png_path, lab_path;
};

FabricPreview::FabricPreview(const FabricColourModel& model, const PreviewSpec& spec) : model_(model), spec_(spec) {}

FabricPreview::~FabricPreview() = default;

Result<std::unique_ptr<FabricPreview>> FabricPreview::open(const FabricColourModel& model, const PreviewSpec& spec,
                                                           const std::filesystem::path& png,
                                                           const std::filesystem::path& lab) {
  std::unique_ptr<FabricPreview> p(new FabricPreview(model, spec));
  p->files_ = std::make_unique<Files>();
  p->files_->png_path = png;
  p->files_->lab_path = lab;
  const int scale = std::max(1, spec.scale);
  p->spec_.scale = scale;
  p->out_width_ = (spec.width_px + static_cast<std::uint32_t>(scale) - 1) / static_cast<std::uint32_t>(scale);
  const std::uint64_t out_height = (std::max<std::uint64_t>(1, spec.height_px) + scale - 1) / scale;
  auto make = [&](const std::filesystem::path& path, OIIO::ImageSpec s,
                  std::unique_ptr<OIIO::ImageOutput>& out) -> Status {
    // pHYs / X-YResolution at the preview's own resolution (the fabric's, divided by the downscale).
    s.attribute("XResolution", static_cast<float>(spec.dpi_x) / static_cast<float>(scale));
    s.attribute("YResolution", static_cast<float>(spec.dpi_y) / static_cast<float>(scale));
    s.attribute("ResolutionUnit", "inch");
    out = OIIO::ImageOutput::create(path.string());
    if (!out || !out->open(path.string(), s))
      return fail(ErrorCode::kOutput, path.string() + ": cannot write: " + (out ? out->geterror() : OIIO::geterror()));
    return {};
  };
  OIIO::ImageSpec ps(static_cast<int>(p->out_width_), static_cast<int>(out_height), 3, OIIO::TypeDesc::UINT8);
  ps.attribute("png:compressionLevel", 3);
  if (auto s = make(png, ps, p->files_->png); !s) return fail(s.error());
  if (!lab.empty()) {
    OIIO::ImageSpec ls(static_cast<int>(p->out_width_), static_cast<int>(out_height), 3, OIIO::TypeDesc::FLOAT);
    ls.channelnames = {"L", "a", "b"};
    ls.alpha_channel = -1;
    ls.attribute("compression", "zip");
    ls.attribute("ImageDescription", "tp printsim fabric colour; channels: CIELAB L*, a*, b* (D50, 2 degree); "
                                     "preview scale " + std::to_string(scale));
    if (auto s = make(lab, ls, p->files_->lab); !s) return fail(s.error());
  }
  p->sums_.assign(p->out_width_, Xyz{});
  p->inked_.assign(p->out_width_, 0);
  p->srgb_row_.resize(static_cast<std::size_t>(p->out_width_) * 3);
  p->lab_row_.resize(static_cast<std::size_t>(p->out_width_) * 3);
  return p;
}

Status FabricPreview::add_row(std::span<const std::uint8_t> levels) {
  const std::size_t nch = model_.inks();
  const auto scale = static_cast<std::uint32_t>(spec_.scale);
  // Only inked pixels are summed; blank ones are counted at flush from the box size.
  for (std::uint32_t x = 0; x < spec_.width_px; ++x) {
    const std::span<const std::uint8_t> p = levels.subspan(static_cast<std::size_t>(x) * nch, nch);
    std::uint64_t key = 0;
    bool any = false;
    for (std::size_t k = 0; k < nch; ++k) {
      any = any || p[k];
      if (k < 8) key |= static_cast<std::uint64_t>(p[k]) << (8 * k);
    }
    if (!any) continue;
    Xyz c;
    if (nch <= 8) {
      auto it = cache_.find(key);
      if (it == cache_.end()) it = cache_.emplace(key, model_.pixel_colour(p)).first;
      c = it->second;
    } else {
      c = model_.pixel_colour(p);
    }
    Xyz& sum = sums_[x / scale];
    sum.x += c.x;
    sum.y += c.y;
    sum.z += c.z;
    ++inked_[x / scale];
  }
  if (++rows_in_ % scale == 0 || rows_in_ == spec_.height_px) return flush();
  return {};
}

Status FabricPreview::flush() {
  const auto scale = static_cast<std::uint32_t>(spec_.scale);
  const auto rows = static_cast<std::uint32_t>(rows_in_ % scale == 0 ? scale : rows_in_ % scale);
  // The PNG is media-relative (the bare fabric shows as sRGB white, as a relative-colorimetric
  // proof does); the CIELAB file keeps the absolute colour.
  const Xyz& w = model_.fabric_white();
  auto relative = [&](const Xyz& c) {
    return device::adapt_bradford({c.x / w.y, c.y / w.y, c.z / w.y}, {w.x / w.y, 1.0, w.z / w.y}, kD50White);
  };
  const Lab white_lab = xyz_to_lab(w);
  const auto white_rgb = xyz_to_srgb8(kD50White);
  for (std::uint32_t px = 0; px < out_width_; ++px) {
    const std::uint32_t cols = std::min(scale, spec_.width_px - px * scale);
    const std::uint32_t n = cols * rows;
    Lab lab = white_lab;
    std::array<std::uint8_t, 3> rgb = white_rgb;
    if (inked_[px]) {
      const double blank = static_cast<double>(n - inked_[px]);
      const Xyz& s = sums_[px];
      const Xyz xyz{(s.x + blank * w.x) / n, (s.y + blank * w.y) / n, (s.z + blank * w.z) / n};
      lab = xyz_to_lab(xyz);
      rgb = xyz_to_srgb8(relative(xyz));
    }
    std::copy(rgb.begin(), rgb.end(), &srgb_row_[static_cast<std::size_t>(px) * 3]);
    float* l = &lab_row_[static_cast<std::size_t>(px) * 3];
    l[0] = static_cast<float>(lab.l);
    l[1] = static_cast<float>(lab.a);
    l[2] = static_cast<float>(lab.b);
  }
  std::fill(sums_.begin(), sums_.end(), Xyz{});
  std::fill(inked_.begin(), inked_.end(), 0);
  const int y = static_cast<int>(out_row_++);
  if (!files_->png->write_scanline(y, 0, OIIO::TypeDesc::UINT8, srgb_row_.data()))
    return fail(ErrorCode::kOutput, files_->png_path.string() + ": " + files_->png->geterror());
  if (files_->lab && !files_->lab->write_scanline(y, 0, OIIO::TypeDesc::FLOAT, lab_row_.data()))
    return fail(ErrorCode::kOutput, files_->lab_path.string() + ": " + files_->lab->geterror());
  return {};
}

Status FabricPreview::close() {
  if (rows_in_ % static_cast<std::uint64_t>(spec_.scale) != 0 && rows_in_ != spec_.height_px)
    if (auto s = flush(); !s) return s;
  if (!files_->png->close()) return fail(ErrorCode::kOutput, files_->png_path.string() + ": " + files_->png->geterror());
  if (files_->lab && !files_->lab->close())
    return fail(ErrorCode::kOutput, files_->lab_path.string() + ": " + files_->lab->geterror());
  return {};
}

}  // namespace tp::sim
