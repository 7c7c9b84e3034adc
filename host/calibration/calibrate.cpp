// host/calibration/calibrate.cpp: targen, the chart job, chart location, measurement, colprof,
// profcheck and the calibration set's manifest.
#include "host/calibration/calibrate.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <vector>

#include "device/model/cgats.h"
#include "device/model/printer_model_file.h"
#include "host/calibration/ink_calibration.h"
#include "host/calibration/internal/chart_print.h"
#include "host/calibration/internal/ink_set_json.h"
#include "host/calibration/light_chart.h"

namespace tp::host {

namespace {

namespace fs = std::filesystem;
using internal::ChartJobExtras;
using internal::fmt;
using internal::run_tool;
using nlohmann::json;

// The first fit line profcheck prints: "... errors(CIEDE2000): max. = 2.41, avg. = 0.62, ...".
void read_fit(const fs::path& log, CalibrateSummary& s) {
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string t = text.str();
  if (std::regex_search(t, m, std::regex(R"(max\. = ([0-9.]+), avg\. = ([0-9.]+))"))) {
    s.fit_max_de00 = std::stod(m[1]);
    s.fit_mean_de00 = std::stod(m[2]);
  }
}

// One chart: targen's device values (spread by `guide` when given), printed as a job, found on the
// fabric and read by the simulated spectrophotometer into `base`.ti3; adds the chart's area.
Status print_and_measure(const CalibrateOptions& o, const fs::path& base, const fs::path& job, const fs::path& printed,
                         const std::optional<fs::path>& guide, const ChartJobExtras& extras, const fs::path& log,
                         double& area_m2) {
  std::error_code ec;
  // 1. The chart's device values (targen: RGB printer, optimised full spread).
  std::vector<std::string> targen{"targen", "-v", "-d2", "-f", std::to_string(o.patches)};
  if (guide) {
    if (!fs::is_regular_file(*guide, ec))
      return fail(ErrorCode::kInvalidArgument, guide->string() + ": no such preconditioning profile");
    targen.insert(targen.end(), {"-c", guide->string()});
  }
  targen.push_back(base.string());
  if (auto st = run_tool("targen", targen, log); !st) return st;
  auto ti1 = device::load_cgats(base.string() + ".ti1");
  if (!ti1) return fail(ErrorCode::kPipeline, "targen output: " + ti1.error().message);
  // 2. and 3. Printed as a job, found on the fabric and read.
  if (auto st = print_chart(o, ti1->front(), base.string() + ".ti1", base, job, printed, extras, log, area_m2); !st)
    return st;
  return check_measurements(base.string() + ".ti3");
}

// The readings of several charts as one measurement file, patches numbered through.
Status merge_measurements(const std::vector<fs::path>& parts, const fs::path& out) {
  device::CgatsTable all;
  for (const fs::path& part : parts) {
    auto t = device::load_cgats(part);
    if (!t) return fail(ErrorCode::kPipeline, t.error().message);
    const device::CgatsTable& table = t->front();
    if (all.fields.empty()) {
      all = table;
      all.rows.clear();
    } else if (table.fields != all.fields) {
      return fail(ErrorCode::kPipeline, part.string() + ": its fields differ from " + parts.front().string() + "'s");
    }
    for (auto row : table.rows) {
      row[static_cast<std::size_t>(all.field("SAMPLE_ID"))] = std::to_string(all.rows.size() + 1);
      all.rows.push_back(std::move(row));
    }
  }
  std::ofstream(out) << device::format_cgats(all);
  return {};
}

}  // namespace

Status check_measurements(const fs::path& ti3) {
  auto tables = device::load_cgats(ti3);
  if (!tables) return fail(ErrorCode::kValidation, tables.error().message);
  const device::CgatsTable& t = tables->front();
  const std::string src = ti3.string();
  if (t.type != "CTI3") return fail(ErrorCode::kValidation, src + ": a measurement file is CTI3, this one is '" + t.type + "'");
  std::vector<std::string> need = {"SAMPLE_ID", "RGB_R", "RGB_G", "RGB_B"};
  const bool xyz = t.field("XYZ_X") >= 0, lab = t.field("LAB_L") >= 0;
  if (!xyz && !lab) return fail(ErrorCode::kValidation, src + ": no measured colour: needs XYZ_X/Y/Z or LAB_L/A/B fields");
  static constexpr const char* kXyz[] = {"XYZ_X", "XYZ_Y", "XYZ_Z"};
  static constexpr const char* kLab[] = {"LAB_L", "LAB_A", "LAB_B"};
  for (const char* f : xyz ? kXyz : kLab) need.emplace_back(f);
  for (const auto& f : need)
    if (t.field(f) < 0) return fail(ErrorCode::kValidation, src + ": field " + f + " missing (an RGB printer's measurements)");
  if (t.rows.size() < 100)
    return fail(ErrorCode::kValidation, src + ": " + std::to_string(t.rows.size()) + " patches; a profile needs at least 100");
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    for (std::size_t k = 1; k < need.size(); ++k) {
      const std::string& v = t.rows[r][static_cast<std::size_t>(t.field(need[k]))];
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      const bool device_field = k <= 3;
      if (end == v.c_str() || *end || !std::isfinite(d) || (device_field && (d < 0 || d > 100)) ||
          (!device_field && xyz && (d < 0 || d > 200)))
        return fail(ErrorCode::kValidation, src + ": patch " + t.rows[r][static_cast<std::size_t>(t.field("SAMPLE_ID"))] + ": " +
                                                need[k] + " = '" + v + "' is not a valid value");
    }
  return {};
}

Result<CalibrateSummary> calibrate(const CalibrateOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.patches < 800 && !o.measurements)
    return fail(ErrorCode::kInvalidArgument, "calibrate: a profiling chart needs at least 800 patches");
  if (o.passes < 1 || o.passes > 3) return fail(ErrorCode::kInvalidArgument, "calibrate: passes must be 1..3");
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) return fail(ErrorCode::kIo, o.out.string() + ": cannot create: " + ec.message());
  const fs::path log = o.out / "calibrate.log";
  const fs::path base = o.out / "profile";
  CalibrateSummary s;
  InkCalibrationResult ink_result;

  if (o.measurements) {
    if (auto st = check_measurements(*o.measurements); !st) return fail(st.error());
    fs::copy_file(*o.measurements, base.string() + ".ti3", fs::copy_options::overwrite_existing, ec);
    if (ec) return fail(ErrorCode::kIo, base.string() + ".ti3: " + ec.message());
  } else {
    // Drop limits, linearisation and ink limit first: the profiling charts print through them.
    ChartJobExtras extras;
    if (o.ink_charts) {
      auto inks = calibrate_inks(o, log);
      if (!inks) return fail(inks.error());
      ink_result = *inks;
      s.chart_area_m2 += inks->chart_area_m2;
      s.ink_charts = inks->charts;
      s.ink_limit_percent = inks->ink_limit_percent;
      extras.calibration = inks->set;
    }
    // Each pass prints and reads a chart; a later pass spreads its patches by the profile the
    // passes before it made (targen -c), and the profile is built from every pass's readings.
    std::vector<fs::path> readings;
    for (int pass = 1; pass <= o.passes; ++pass) {
      const bool last = pass == o.passes;
      const std::string tag = last ? std::string() : "-" + std::to_string(pass);
      const fs::path pass_base = o.out / ("pass" + std::to_string(pass));
      std::optional<fs::path> guide = o.precondition;
      if (pass > 1) {
        const fs::path previous = o.out / ("pass" + std::to_string(pass - 1));
        if (auto st = merge_measurements(readings, previous.string() + "-all.ti3"); !st) return fail(st.error());
        if (auto st = run_tool("colprof (pass " + std::to_string(pass - 1) + ")",
                               {"colprof", "-v", "-ql", "-D", "tp calibration pass", previous.string() + "-all"}, log);
            !st)
          return fail(st.error());
        guide = previous.string() + "-all.icc";
      }
      if (auto st = print_and_measure(o, pass_base, o.out / ("chart-job" + tag), o.out / ("chart-printed" + tag), guide,
                                      extras, log, s.chart_area_m2);
          !st)
        return fail(st.error());
      readings.push_back(pass_base.string() + ".ti3");
    }
    // The light corner, densely: the spread charts leave it a few patches (light_chart.h).
    if (o.light_chart) {
      const fs::path light = o.out / "light";
      const device::CgatsTable ti1 = light_chart();
      std::ofstream(light.string() + ".ti1") << device::format_cgats(ti1);
      if (auto st = internal::print_chart(o, ti1, light.string() + ".ti1", light, o.out / "chart-job-light",
                                          o.out / "chart-printed-light", extras, log, s.chart_area_m2);
          !st)
        return fail(st.error().with_context("light chart"));
      if (auto st = check_measurements(light.string() + ".ti3"); !st) return fail(st.error());
      readings.push_back(light.string() + ".ti3");
      s.light_patches = static_cast<int>(ti1.rows.size());
    }
    if (auto st = merge_measurements(readings, base.string() + ".ti3"); !st) return fail(st.error());
  }
  // 4. The profile, and how well it fits its own measurements.
  if (auto st = run_tool("colprof", {"colprof", "-v", "-q" + o.quality, "-D", "tp " + o.fabric + " calibration", base.string()}, log);
      !st)
    return fail(st.error());
  const fs::path fit_log = o.out / "profcheck.log";
  if (auto st = run_tool("profcheck", {"profcheck", "-k", base.string() + ".ti3", base.string() + ".icc"}, fit_log); !st)
    return fail(st.error());
  read_fit(fit_log, s);
  auto measured = device::load_cgats(base.string() + ".ti3");
  s.patches = measured ? static_cast<int>(measured->front().rows.size()) : 0;
  s.profile = base.string() + ".icc";
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // 5. The set's manifest.
  json m = {{"format", "tp-calibration/1"},
            {"printer_model", o.printer_model ? o.printer_model->string() : std::string("built-in")},
            {"fabric", o.fabric},
            {"profile", "profile.icc"},
            {"profile_kind", "rgb-through-separation"},
            {"measurements", "profile.ti3"},
            {"source", o.measurements ? "measurements file" : "printsim measure"},
            {"precondition", o.precondition ? o.precondition->string() : std::string()},
            {"patches", s.patches},
            {"chart_area_m2", s.chart_area_m2},
            {"fit_de00", {{"mean", s.fit_mean_de00}, {"max", s.fit_max_de00}}},
            {"seconds", s.seconds},
            {"ink_charts", s.ink_charts},
            {"light_patches", s.light_patches}};
  internal::add_ink_fields(m, ink_result.inks, ink_result.ink_limit_percent);
  std::ofstream(o.out / "calibration.json") << m.dump(2) << "\n";
  return s;
}

}  // namespace tp::host
