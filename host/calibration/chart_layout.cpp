// host/calibration/chart_layout.cpp: patch grid, frame and orientation mark.
#include "host/calibration/chart_layout.h"

#include <algorithm>
#include <cmath>

namespace tp::host {

Result<ChartLayout> layout_chart(const device::CgatsTable& ti1, const std::string& source, const ChartGeometry& g) {
  const int fid = ti1.field("SAMPLE_ID"), fr = ti1.field("RGB_R"), fg = ti1.field("RGB_G"), fb = ti1.field("RGB_B");
  if (fid < 0 || fr < 0 || fg < 0 || fb < 0)
    return fail(ErrorCode::kValidation, source + ": an RGB chart needs SAMPLE_ID, RGB_R, RGB_G and RGB_B fields");
  if (ti1.rows.empty()) return fail(ErrorCode::kValidation, source + ": no patches");
  ChartLayout c;
  c.geometry = g;
  const int n = static_cast<int>(ti1.rows.size());
  const int rows = (n + g.columns - 1) / g.columns;
  const double inset = g.frame_mm + g.gap_mm;
  c.width_mm = 2 * inset + g.columns * g.patch_mm;
  c.height_mm = 2 * inset + rows * g.patch_mm;
  for (int i = 0; i < n; ++i) {
    const auto& row = ti1.rows[static_cast<std::size_t>(i)];
    ChartLayout::Patch p;
    p.id = row[static_cast<std::size_t>(fid)];
    for (int k = 0; k < 3; ++k) {
      const std::string& v = row[static_cast<std::size_t>(k == 0 ? fr : k == 1 ? fg : fb)];
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end || !(d >= 0 && d <= 100))
        return fail(ErrorCode::kValidation, source + ": patch " + p.id + ": device value '" + v + "' is not in 0..100");
      p.rgb_pct[static_cast<std::size_t>(k)] = d;
    }
    p.x_mm = inset + (i % g.columns + 0.5) * g.patch_mm;
    p.y_mm = inset + (i / g.columns + 0.5) * g.patch_mm;
    c.patches.push_back(std::move(p));
  }
  c.mark_x_mm = g.frame_mm + 0.5 * g.gap_mm;
  c.mark_y_mm = g.frame_mm + 0.5 * g.gap_mm;

  // The picture: white, black frame, the mark, then the patches.
  const int w = static_cast<int>(std::lround(c.width_mm * g.px_per_mm));
  const int h = static_cast<int>(std::lround(c.height_mm * g.px_per_mm));
  c.image.width_px = w;
  c.image.height_px = h;
  c.image.pixels.assign(static_cast<std::size_t>(w) * h, geometry::Rgba8{255, 255, 255, 255});
  auto fill = [&](double x0, double y0, double x1, double y1, geometry::Rgba8 colour) {
    const int px0 = static_cast<int>(std::lround(x0 * g.px_per_mm)), px1 = static_cast<int>(std::lround(x1 * g.px_per_mm));
    const int py0 = static_cast<int>(std::lround(y0 * g.px_per_mm)), py1 = static_cast<int>(std::lround(y1 * g.px_per_mm));
    for (int y = std::max(0, py0); y < std::min(h, py1); ++y)
      for (int x = std::max(0, px0); x < std::min(w, px1); ++x) c.image.pixels[static_cast<std::size_t>(y) * w + x] = colour;
  };
  const geometry::Rgba8 black{0, 0, 0, 255};
  fill(0, 0, c.width_mm, g.frame_mm, black);
  fill(0, c.height_mm - g.frame_mm, c.width_mm, c.height_mm, black);
  fill(0, 0, g.frame_mm, c.height_mm, black);
  fill(c.width_mm - g.frame_mm, 0, c.width_mm, c.height_mm, black);
  fill(g.frame_mm, g.frame_mm, g.frame_mm + g.gap_mm, g.frame_mm + g.gap_mm, black);
  for (const auto& p : c.patches) {
    auto q = [](double pct) { return static_cast<std::uint8_t>(std::lround(pct * 2.55)); };
    fill(p.x_mm - 0.5 * g.patch_mm, p.y_mm - 0.5 * g.patch_mm, p.x_mm + 0.5 * g.patch_mm, p.y_mm + 0.5 * g.patch_mm,
         geometry::Rgba8{q(p.rgb_pct[0]), q(p.rgb_pct[1]), q(p.rgb_pct[2]), 255});
  }
  return c;
}

}  // namespace tp::host
