// host/calibration/ink_calibration.cpp: drop-limit, linearisation and ink-limit charts: their
// device values, printing, reading and the set they make.
#include "host/calibration/ink_calibration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "device/model/printer_model_file.h"
#include "host/calibration/drop_limit.h"
#include "host/calibration/ink_limit.h"
#include "host/calibration/internal/chart_print.h"
#include "host/calibration/internal/ink_set_json.h"
#include "host/calibration/linearisation.h"

namespace tp::host {

namespace {

/// Slack of a ramp's end test and of equal amounts, so a step landing on 1 up to rounding is kept.
constexpr double kStepSlack = 1e-9;

namespace fs = std::filesystem;
using internal::fmt;

constexpr int kReplicates = 2;  ///< each amount printed twice (the instrument's noise averages)
constexpr int kUnprinted = 4;   ///< bare fabric patches per chart
constexpr double kDropChartFrom = 0.5, kDropChartStep = 0.025;
constexpr double kLinearChartStep = 0.05;
constexpr double kInkLimitFrom = 0.3, kInkLimitStep = 0.05;

bool is_black(const std::string& name) { return name == "black" || name == "k"; }

// A device-value chart: per patch the three channels' ink amounts (0..1; R, G, B = 1 - amount).
device::CgatsTable device_chart(const std::vector<std::array<double, 3>>& amounts) {
  device::CgatsTable t;
  t.type = "CTI1";
  t.keywords = {{"DESCRIPTOR", "tp device-value calibration chart"}, {"COLOR_REP", "RGB"}};
  t.fields = {"SAMPLE_ID", "RGB_R", "RGB_G", "RGB_B"};
  for (int i = 0; i < kUnprinted; ++i) t.rows.push_back({std::to_string(t.rows.size() + 1), "100", "100", "100"});
  for (const auto& a : amounts)
    t.rows.push_back({std::to_string(t.rows.size() + 1), fmt(100 * (1 - a[0]), 4), fmt(100 * (1 - a[1]), 4),
                      fmt(100 * (1 - a[2]), 4)});
  return t;
}

// Amounts from..1 by step, each kReplicates times, on channel `k` alone.
void add_ramp(std::vector<std::array<double, 3>>& out, int k, double from, double step) {
  for (int i = 0; from + i * step <= 1 + kStepSlack; ++i)
    for (int r = 0; r < kReplicates; ++r) {
      std::array<double, 3> a{0, 0, 0};
      a[static_cast<size_t>(k)] = std::min(1.0, from + i * step);
      out.push_back(a);
    }
}

// A set without a profile: what the later charts print through.
Status write_ink_set(const fs::path& path, const CalibrateOptions& o, const std::vector<InkCalibration>& inks,
                     double limit) {
  nlohmann::json m = {{"format", "tp-calibration/1"}, {"fabric", o.fabric}, {"profile", nullptr}};
  internal::add_ink_fields(m, inks, limit);
  std::ofstream out(path);
  out << m.dump(2) << "\n";
  if (!out) return fail(ErrorCode::kIo, path.string() + ": cannot write");
  return {};
}

// One chart printed and read; its readings.
Result<std::vector<DeviceReading>> print_device_chart(const CalibrateOptions& o, const std::string& name,
                                                      const std::vector<std::array<double, 3>>& amounts,
                                                      const internal::ChartJobExtras& extras, const fs::path& log,
                                                      InkCalibrationResult& r) {
  const fs::path base = o.out / name;
  const device::CgatsTable ti1 = device_chart(amounts);
  std::ofstream(base.string() + ".ti1") << device::format_cgats(ti1);
  if (auto st = internal::print_chart(o, ti1, base.string() + ".ti1", base, o.out / (name + "-job"),
                                      o.out / (name + "-printed"), extras, log, r.chart_area_m2);
      !st)
    return fail(ErrorCode::kPipeline, name + " chart: " + st.error().message);
  ++r.charts;
  return read_device_readings(base.string() + ".ti3");
}

}  // namespace

Result<InkCalibrationResult> calibrate_inks(const CalibrateOptions& o, const fs::path& log) {
  device::PrinterModel model;
  if (o.printer_model) {
    auto m = device::load_printer_model(*o.printer_model);
    if (!m) return fail(ErrorCode::kValidation, m.error().message);
    model = *m;
  }
  InkCalibrationResult r;
  for (const auto& ink : model.inks) r.inks.push_back({ink.name, 1.0, {}});
  const size_t n = r.inks.size();
  r.set = o.out / "ink-set.json";

  // 1. Drop limits: three inks a chart, each on its own channel, raw device values.
  for (size_t first = 0; first < n; first += 3) {
    internal::ChartJobExtras extras;
    std::vector<std::array<double, 3>> amounts;
    for (size_t c = first; c < std::min(n, first + 3); ++c) {
      extras.device_inks.push_back(r.inks[c].name);
      add_ramp(amounts, static_cast<int>(c - first), kDropChartFrom, kDropChartStep);
    }
    auto readings = print_device_chart(o, "drop-limit-" + std::to_string(first / 3 + 1), amounts, extras, log, r);
    if (!readings) return fail(readings.error());
    for (size_t c = first; c < std::min(n, first + 3); ++c) {
      auto d =
          drop_limit(single_channel_ramp(*readings, static_cast<int>(c - first)), r.inks[c].name, o.drop_limit_de00);
      if (!d) return fail(d.error());
      r.inks[c].drop_limit = *d;
      r.inks[c].linearisation.points = {{0.0, 0.0}, {1.0, *d}};
    }
  }
  if (auto st = write_ink_set(r.set, o, r.inks, 0); !st) return fail(st.error());

  // 2. One linearisation chart per ink, printed through the drop limits.
  std::vector<InkCalibration> linearised = r.inks;
  for (size_t c = 0; c < n; ++c) {
    std::vector<std::array<double, 3>> amounts;
    add_ramp(amounts, 0, 0, kLinearChartStep);
    auto readings =
        print_device_chart(o, "linearisation-" + r.inks[c].name, amounts, {{r.inks[c].name}, r.set}, log, r);
    if (!readings) return fail(readings.error());
    auto curve = linearisation_curve(single_channel_ramp(*readings, 0), r.inks[c].drop_limit, r.inks[c].name);
    if (!curve) return fail(curve.error());
    linearised[c].linearisation = *curve;
  }
  r.inks = linearised;
  if (auto st = write_ink_set(r.set, o, r.inks, 0); !st) return fail(st.error());

  // 3. The ink limit: up to three colour inks overprinted in equal requests, through the curves;
  // each patch's total is what the curves lay.
  std::vector<size_t> colour;
  for (size_t c = 0; c < n && colour.size() < 3; ++c)
    if (!is_black(r.inks[c].name)) colour.push_back(c);
  if (colour.size() >= 2) {
    internal::ChartJobExtras extras{{}, r.set};
    for (size_t c : colour) extras.device_inks.push_back(r.inks[c].name);
    std::vector<std::array<double, 3>> amounts;
    for (int i = 0; kInkLimitFrom + i * kInkLimitStep <= 1 + kStepSlack; ++i)
      for (int k = 0; k < kReplicates; ++k) {
        const double a = std::min(1.0, kInkLimitFrom + i * kInkLimitStep);
        amounts.push_back({a, colour.size() > 1 ? a : 0.0, colour.size() > 2 ? a : 0.0});
      }
    auto readings = print_device_chart(o, "ink-limit", amounts, extras, log, r);
    if (!readings) return fail(readings.error());
    // Patches with the used channels equal: total laid = sum of each ink's curve at the request.
    std::vector<RampPoint> ramp;
    for (const auto& reading : *readings) {
      const double request = 1 - reading.rgb_pct[0] / 100;
      bool same = true;
      for (size_t k = 1; k < colour.size(); ++k)
        same = same && std::abs(reading.rgb_pct[k] - reading.rgb_pct[0]) < 1e-6;
      if (!same || request <= 0) continue;
      double total = 0;
      for (size_t c : colour) total += rip::evaluate(r.inks[c].linearisation, request);
      if (!ramp.empty() && std::abs(ramp.back().amount - total) < kStepSlack) {
        // A replicate: average it in.
        RampPoint& p = ramp.back();
        p.lab = {(p.lab.l + reading.lab.l) / 2, (p.lab.a + reading.lab.a) / 2, (p.lab.b + reading.lab.b) / 2};
        continue;
      }
      ramp.push_back({total, reading.lab});
    }
    std::sort(ramp.begin(), ramp.end(), [](const RampPoint& a, const RampPoint& b) { return a.amount < b.amount; });
    auto limit = ink_limit_percent(ramp);
    if (!limit) return fail(limit.error());
    r.ink_limit_percent = std::min(*limit, 100.0 * static_cast<double>(n));
  }
  if (auto st = write_ink_set(r.set, o, r.inks, r.ink_limit_percent); !st) return fail(st.error());
  return r;
}

}  // namespace tp::host
