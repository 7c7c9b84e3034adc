// simulator/fabric/spectro_measure.cpp: aperture averaging in XYZ, noise, .ti3 writing.
#include "simulator/fabric/spectro_measure.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <vector>

#include "device/model/cgats.h"
#include "device/colour/colorimetry.h"
#include "simulator/fabric/fabric_preset.h"

namespace tp::sim {

namespace {

std::string fmt(double v, int decimals) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

}  // namespace

Result<MeasureSummary> measure_chart(const MeasureOptions& o) {
  auto tables = device::load_cgats(o.chart);
  if (!tables) return fail(ErrorCode::kInvalidArgument, "chart: " + tables.error().message);
  const device::CgatsTable& chart = tables->front();
  const int fx = chart.field("TP_X_MM"), fy = chart.field("TP_Y_MM"), fid = chart.field("SAMPLE_ID");
  if (fx < 0 || fy < 0 || fid < 0)
    return fail(ErrorCode::kInvalidArgument, o.chart.string() + ": chart layout needs SAMPLE_ID, TP_X_MM and TP_Y_MM fields");
  if (!(o.aperture_mm > 0 && o.aperture_mm <= 50))
    return fail(ErrorCode::kInvalidArgument, "aperture must be in (0, 50] mm, got " + fmt(o.aperture_mm, 2));

  // The fabric's colour image, at its preview resolution.
  auto in = OIIO::ImageInput::open(o.fabric_lab.string());
  if (!in) return fail(ErrorCode::kInvalidArgument, o.fabric_lab.string() + ": cannot read: " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  if (spec.nchannels != 3) return fail(ErrorCode::kInvalidArgument, o.fabric_lab.string() + ": expected 3 channels (L*, a*, b*)");
  const float dpi = spec.get_float_attribute("XResolution", 0);
  if (!(dpi > 0)) return fail(ErrorCode::kInvalidArgument, o.fabric_lab.string() + ": no XResolution");
  std::vector<float> lab(static_cast<std::size_t>(spec.width) * spec.height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, lab.data()))
    return fail(ErrorCode::kInvalidArgument, o.fabric_lab.string() + ": " + in->geterror());
  const double px_per_mm = dpi / 25.4;
  const double r_px = 0.5 * o.aperture_mm * px_per_mm;

  // Device fields pass through: everything but the layout.
  device::CgatsTable out;
  out.type = "CTI3";
  out.keywords = {{"DESCRIPTOR", "tp printsim simulated spectrophotometer"},
                  {"ORIGINATOR", "tp printsim measure"},
                  {"DEVICE_CLASS", "OUTPUT"},
                  {"APERTURE_MM", fmt(o.aperture_mm, 2)}};
  std::string rep = chart.keyword("COLOR_REP");
  if (rep.empty()) rep = "CMYK";
  out.keywords.emplace_back("COLOR_REP", rep + "_XYZ");
  if (auto limit = chart.keyword("TOTAL_INK_LIMIT"); !limit.empty()) out.keywords.emplace_back("TOTAL_INK_LIMIT", limit);
  std::vector<int> keep;
  for (std::size_t i = 0; i < chart.fields.size(); ++i)
    if (chart.fields[i] != "TP_X_MM" && chart.fields[i] != "TP_Y_MM") {
      keep.push_back(static_cast<int>(i));
      out.fields.push_back(chart.fields[i]);
    }
  for (const char* f : {"XYZ_X", "XYZ_Y", "XYZ_Z"}) out.fields.push_back(f);

  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> noise(0.0, o.noise_de > 0 ? o.noise_de : 1.0);
  MeasureSummary summary;
  summary.min_samples = 1e300;
  for (const auto& row : chart.rows) {
    const std::string& id = row[static_cast<std::size_t>(fid)];
    double cx = 0, cy = 0;
    try {
      cx = std::stod(row[static_cast<std::size_t>(fx)]) * px_per_mm;
      cy = std::stod(row[static_cast<std::size_t>(fy)]) * px_per_mm;
    } catch (const std::exception&) {
      return fail(ErrorCode::kInvalidArgument, o.chart.string() + ": patch " + id + ": TP_X_MM / TP_Y_MM not numbers");
    }
    if (cx - r_px < 0 || cy - r_px < 0 || cx + r_px > spec.width || cy + r_px > spec.height)
      return fail(ErrorCode::kInvalidArgument, o.chart.string() + ": patch " + id + ": aperture leaves the fabric image " +
                                                  o.fabric_lab.string());
    // An instrument integrates light: average XYZ (not Lab) over the spot.
    Xyz sum;
    int n = 0;
    for (int y = static_cast<int>(std::floor(cy - r_px)); y <= static_cast<int>(std::ceil(cy + r_px)); ++y)
      for (int x = static_cast<int>(std::floor(cx - r_px)); x <= static_cast<int>(std::ceil(cx + r_px)); ++x) {
        if (x < 0 || y < 0 || x >= spec.width || y >= spec.height) continue;
        const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
        if (dx * dx + dy * dy > r_px * r_px) continue;
        const float* p = &lab[(static_cast<std::size_t>(y) * spec.width + x) * 3];
        const Xyz c = lab_to_xyz({p[0], p[1], p[2]});
        sum.x += c.x;
        sum.y += c.y;
        sum.z += c.z;
        ++n;
      }
    if (n == 0) return fail(ErrorCode::kInvalidArgument, o.chart.string() + ": patch " + id + ": aperture covers no pixel");
    summary.min_samples = std::min<double>(summary.min_samples, n);
    Xyz mean{sum.x / n, sum.y / n, sum.z / n};
    if (o.noise_de > 0) {
      Lab l = xyz_to_lab(mean);
      l.l += noise(rng);
      l.a += noise(rng);
      l.b += noise(rng);
      mean = lab_to_xyz(l);
    }
    std::vector<std::string> r;
    for (int k : keep) r.push_back(row[static_cast<std::size_t>(k)]);
    r.push_back(fmt(100 * mean.x, 5));
    r.push_back(fmt(100 * mean.y, 5));
    r.push_back(fmt(100 * mean.z, 5));
    out.rows.push_back(std::move(r));
  }
  summary.patches = out.rows.size();
  std::ofstream f(o.out_ti3, std::ios::binary);
  f << device::format_cgats(out);
  if (!f) return fail(ErrorCode::kOutput, o.out_ti3.string() + ": cannot write");
  return summary;
}

}  // namespace tp::sim
