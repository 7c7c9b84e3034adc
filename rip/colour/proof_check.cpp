// rip/colour/proof_check.cpp: cell averaging of both images, white estimate, CIEDE2000 statistics.
#include "rip/colour/proof_check.h"

#include <lcms2.h>

#include "rip/colour/internal/lcms_handles.h"
#include "rip/colour/lab_image.h"
#include "rip/colour/profile_inverse.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tp::rip {

namespace {

using device::Lab;
using device::Xyz;

struct Cells {
  int nx = 0, ny = 0;
  std::vector<double> x, y, z;   // summed XYZ
  std::vector<std::uint32_t> n;  // samples
  std::vector<std::uint8_t> blank_px;  // design only: the cell holds a white pixel

  void init(int w, int h) {
    nx = w;
    ny = h;
    const auto size = static_cast<std::size_t>(w) * h;
    x.assign(size, 0);
    y.assign(size, 0);
    z.assign(size, 0);
    n.assign(size, 0);
    blank_px.assign(size, 0);
  }
  Xyz mean(std::size_t i) const { return {x[i] / n[i], y[i] / n[i], z[i] / n[i]}; }
};

// Adds every pixel of `r` to the cell its centre lies in; `to_xyz` converts one pixel.
template <class F>
void accumulate(const Image3f& r, double cell_mm, Cells& c, F&& to_xyz) {
  const double cell_px = cell_mm * r.px_per_mm;
  for (int py = 0; py < r.height_px; ++py) {
    const int cy = static_cast<int>((py + 0.5) / cell_px);
    if (cy >= c.ny) break;
    for (int px = 0; px < r.width_px; ++px) {
      const int cx = static_cast<int>((px + 0.5) / cell_px);
      if (cx >= c.nx) break;
      const std::size_t i = static_cast<std::size_t>(cy) * c.nx + cx;
      const float* p = &r.px[(static_cast<std::size_t>(py) * r.width_px + px) * 3];
      bool white = false;
      const Xyz v = to_xyz(p, white);
      c.x[i] += v.x;
      c.y[i] += v.y;
      c.z[i] += v.z;
      ++c.n[i];
      if (white) c.blank_px[i] = 1;
    }
  }
}

}  // namespace

Result<ProofCheckResult> check_proof(const std::filesystem::path& design, const std::filesystem::path& fabric_lab,
                                     double cell_mm, const std::filesystem::path& printer_profile) {
  // Lab -> printer -> Lab, relative colorimetric: how close the printer gets to each colour.
  lcms::Transform to_dev, from_dev;
  std::unique_ptr<RgbProfileInverse> inverse;
  cmsUInt32Number dev_fmt = 0;
  if (!printer_profile.empty()) {
    lcms::Profile prof(cmsOpenProfileFromFile(printer_profile.string().c_str(), "r"));
    if (!prof) return fail(ErrorCode::kColour, printer_profile.string() + ": not a readable ICC profile");
    lcms::Profile lab(cmsCreateLab4Profile(nullptr));
    if (cmsGetColorSpace(prof.get()) == cmsSigRgbData) {
      auto inv = RgbProfileInverse::open(printer_profile);
      if (!inv) return fail(inv.error());
      inverse = std::make_unique<RgbProfileInverse>(std::move(*inv));
    }
    const int nch = static_cast<int>(cmsChannelsOf(cmsGetColorSpace(prof.get())));
    dev_fmt = FLOAT_SH(1) | CHANNELS_SH(nch) | BYTES_SH(0);
    if (!inverse) {
      to_dev.reset(cmsCreateTransform(lab.get(), TYPE_Lab_DBL, prof.get(), dev_fmt, INTENT_RELATIVE_COLORIMETRIC,
                                      cmsFLAGS_NOCACHE));
      from_dev.reset(cmsCreateTransform(prof.get(), dev_fmt, lab.get(), TYPE_Lab_DBL, INTENT_RELATIVE_COLORIMETRIC,
                                        cmsFLAGS_NOCACHE));
    }
    if (!inverse && (!to_dev || !from_dev))
      return fail(ErrorCode::kColour, printer_profile.string() + ": lcms2 cannot build the gamut round trip");
  }
  if (!(cell_mm >= 0.1 && cell_mm <= 50)) return fail(ErrorCode::kInvalidArgument, "proof check: cell must be 0.1..50 mm");
  auto d = read_image3f(design);
  if (!d) return fail(d.error());
  auto f = read_image3f(fabric_lab);
  if (!f) return fail(f.error());
  // The common extent of both, in whole cells.
  const double w_mm = std::min(d->width_px / d->px_per_mm, f->width_px / f->px_per_mm);
  const double h_mm = std::min(d->height_px / d->px_per_mm, f->height_px / f->px_per_mm);
  Cells dc, fc;
  const int nx = static_cast<int>(w_mm / cell_mm), ny = static_cast<int>(h_mm / cell_mm);
  if (nx < 3 || ny < 3) return fail(ErrorCode::kInvalidArgument, "proof check: images smaller than 3 x 3 cells");
  dc.init(nx, ny);
  fc.init(nx, ny);
  accumulate(*d, cell_mm, dc, [](const float* p, bool& white) {
    auto q = [](float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); };
    const std::uint8_t r = q(p[0]), g = q(p[1]), b = q(p[2]);
    white = r >= 250 && g >= 250 && b >= 250;
    return device::srgb8_to_xyz(r, g, b);
  });
  accumulate(*f, cell_mm, fc, [](const float* p, bool& white) {
    white = false;
    return device::lab_to_xyz({p[0], p[1], p[2]});
  });

  // Printed: the cell and its neighbours hold no white design pixel. Blank: all of them white.
  ProofCheckResult out;
  out.cell_mm = cell_mm;
  std::vector<std::size_t> printed;
  Xyz white_sum;
  for (int y = 1; y + 1 < ny; ++y)
    for (int x = 1; x + 1 < nx; ++x) {
      bool any_blank = false, all_blank = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::size_t j = static_cast<std::size_t>(y + dy) * nx + (x + dx);
          any_blank = any_blank || dc.blank_px[j];
          const Xyz m = dc.mean(j);
          all_blank = all_blank && dc.blank_px[j] && m.y > 0.98;
        }
      const std::size_t i = static_cast<std::size_t>(y) * nx + x;
      if (!dc.n[i] || !fc.n[i]) continue;
      // Colour edges in the design (stripes, outlines) are left out: there a fraction of a cell
      // of registration is a large difference that says nothing about colour.
      bool flat = true;
      if (!any_blank) {
        const Lab centre = device::xyz_to_lab(dc.mean(i));
        for (int dy = -1; dy <= 1 && flat; ++dy)
          for (int dx = -1; dx <= 1 && flat; ++dx) {
            const std::size_t j = static_cast<std::size_t>(y + dy) * nx + (x + dx);
            flat = device::delta_e_2000(centre, device::xyz_to_lab(dc.mean(j))) <= kFlatDesign_de00;
          }
        if (!flat) ++out.edge_cells;
      }
      if (!any_blank && flat) printed.push_back(i);
      if (all_blank) {
        const Xyz m = fc.mean(i);
        white_sum.x += m.x;
        white_sum.y += m.y;
        white_sum.z += m.z;
        ++out.blank_cells;
      }
    }
  if (printed.empty()) return fail(ErrorCode::kInvalidArgument, design.string() + ": no printed area to compare");
  if (!out.blank_cells) return fail(ErrorCode::kInvalidArgument, design.string() + ": no unprinted area to measure the fabric white on");
  const Xyz w{white_sum.x / out.blank_cells, white_sum.y / out.blank_cells, white_sum.z / out.blank_cells};
  out.fabric_white = device::xyz_to_lab(w);
  std::vector<double> de;
  de.reserve(printed.size());
  double oog_worst = 0;
  // An RGB profile (a calibration set's) is inverted as the RIP inverts it (profile_inverse.h).
  std::vector<Lab> wants, reproduced;
  for (std::size_t i : printed) wants.push_back(device::xyz_to_lab(dc.mean(i)));
  if (inverse) reproduced = inverse->colour_of(inverse->device_for(wants));
  for (std::size_t k = 0; k < printed.size(); ++k) {
    const std::size_t i = printed[k];
    const Lab want = wants[k];
    if (to_dev || inverse) {
      Lab back;
      if (inverse) {
        back = reproduced[k];
      } else {
        double dev[16] = {};
        cmsCIELab in{want.l, want.a, want.b}, out{};
        cmsDoTransform(to_dev.get(), &in, dev, 1);
        cmsDoTransform(from_dev.get(), dev, &out, 1);
        back = {out.L, out.a, out.b};
      }
      const double gap = device::delta_e_2000(want, back);
      if (gap > kGamutTolerance_de00) {
        ++out.out_of_gamut_cells;
        oog_worst = std::max(oog_worst, gap);
        continue;
      }
    }
    const Xyz fm = fc.mean(i);
    // Media-relative the ICC way: Bradford from the fabric white to D50, scaled to Y = 1.
    const Xyz rel = device::adapt_bradford({fm.x / w.y, fm.y / w.y, fm.z / w.y}, {w.x / w.y, 1.0, w.z / w.y}, device::kD50White);
    const Lab got = device::xyz_to_lab(rel);
    de.push_back(device::delta_e_2000(want, got));
    out.bias.l += got.l - want.l;
    out.bias.a += got.a - want.a;
    out.bias.b += got.b - want.b;
  }
  out.out_of_gamut_share = static_cast<double>(out.out_of_gamut_cells) / static_cast<double>(printed.size());
  out.out_of_gamut_worst_de00 = oog_worst;
  if (de.empty()) return fail(ErrorCode::kInvalidArgument, design.string() + ": every printed cell is out of the printer's gamut");
  const auto compared = static_cast<double>(de.size());
  out.bias = {out.bias.l / compared, out.bias.a / compared, out.bias.b / compared};
  std::sort(de.begin(), de.end());
  double sum = 0;
  for (double v : de) sum += v;
  out.cells = de.size();
  out.mean_de00 = sum / static_cast<double>(de.size());
  out.p95_de00 = de[std::min(de.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(de.size())))];
  out.max_de00 = de.back();
  return out;
}

}  // namespace tp::rip
