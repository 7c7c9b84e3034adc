// host/calibration/calibrate.cpp: targen, the chart job, chart location, measurement, colprof,
// profcheck and the calibration set's manifest.
#include "host/calibration/calibrate.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <vector>

#include "device/model/cgats.h"
#include "device/model/printer_model_file.h"
#include "host/calibration/chart_layout.h"
#include "rip/colour/lab_image.h"
#include "rip/image/image_io.h"

extern char** environ;

namespace tp::host {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Runs a program, its output appended to `log`; fails naming the step and the log.
Status run_tool(const std::string& step, const std::vector<std::string>& argv, const fs::path& log) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return fail(ErrorCode::kIo, step + ": cannot run " + argv[0] + " (is package argyll installed?)");
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return fail(ErrorCode::kPipeline, step + ": " + argv[0] + " failed; see " + log.string());
  return {};
}

fs::path own_dir() {
  std::error_code ec;
  return fs::read_symlink("/proc/self/exe", ec).parent_path();
}

std::string fmt(double v, int decimals = 3) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

// The flat job that prints the chart: one rectangular piece carrying the chart picture.
Status write_chart_job(const fs::path& dir, const ChartLayout& chart, const CalibrateOptions& o) {
  fs::create_directories(dir);
  if (auto s = rip::write_png(dir / "chart.png", chart.image, rip::PngChannels::kRgba, chart.geometry.px_per_mm * 25.4); !s)
    return fail(ErrorCode::kIo, "chart picture: " + s.error().message);
  const double w = chart.width_mm, h = chart.height_mm;
  json piece = {{"name", "chart"},
                {"edges", json::array({json{{"name", "top"}, {"from", {0.0, 0.0}}}, json{{"name", "right"}, {"from", {w, 0.0}}},
                                       json{{"name", "bottom"}, {"from", {w, h}}}, json{{"name", "left"}, {"from", {0.0, h}}}})}};
  json pattern = {{"format", "tp-pattern"}, {"version", 1}, {"name", "calibration_chart"}, {"units", "mm"},
                  {"pieces", json::array({piece})}};
  std::ofstream(dir / "pattern.json") << pattern.dump(1) << "\n";
  device::PrinterModel model;
  if (o.printer_model) {
    auto m = device::load_printer_model(*o.printer_model);
    if (!m) return fail(ErrorCode::kValidation, m.error().message);
    model = *m;
  }
  model.fabric = o.fabric;
  if (auto s = device::validate_printer_model(model); !s) return fail(ErrorCode::kValidation, s.error().message);
  std::ofstream(dir / "printer.tpm") << device::format_printer_model(model);
  json job = {{"format", "tp-job/1"},
              {"name", "calibration-chart"},
              {"garment", {{"pattern", "pattern.json"}}},
              {"design", {{"layers", json::array({json{{"type", "planar"},
                                                       {"name", "chart"},
                                                       {"image", "chart.png"},
                                                       {"centre", {w / 2, h / 2, 0.0}},
                                                       {"normal", {0, 0, 1}},
                                                       {"up", {0, 1, 0}},
                                                       {"width", std::to_string(w) + " mm"}}})}}},
              {"finishing", {{"seam_allowance", "1 mm"}, {"hem_allowance", "1 mm"}, {"notches", false}, {"labels", "none"}}},
              {"marker", {{"fabric_width", std::to_string(std::ceil(w + 60)) + " mm"}, {"rotations", "fixed"}, {"time_limit_s", 1}}},
              {"print", {{"printer", "sim"}, {"printer_model", "printer.tpm"}, {"dpi", o.dpi}, {"passes", 1}, {"preview_dpi", 40}}}};
  std::ofstream(dir / "job.json") << job.dump(1) << "\n";
  return {};
}

// Where the chart landed: the black frame's bounding box, and which way round (the mark's corner).
struct Placement {
  double x0_mm = 0, y0_mm = 0, sx = 1, sy = 1;  // fabric = origin + scale * chart (negative: flipped)
};

Result<Placement> locate_chart(const rip::Image3f& lab, const ChartLayout& chart, const fs::path& source) {
  int x0 = lab.width_px, y0 = lab.height_px, x1 = -1, y1 = -1;
  for (int y = 0; y < lab.height_px; ++y)
    for (int x = 0; x < lab.width_px; ++x)
      if (lab.at(x, y)[0] < 30.f) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
  if (x1 < 0) return fail(ErrorCode::kPipeline, source.string() + ": the chart's black frame is not on the fabric");
  const double bx0 = x0 / lab.px_per_mm, by0 = y0 / lab.px_per_mm;
  const double bx1 = (x1 + 1) / lab.px_per_mm, by1 = (y1 + 1) / lab.px_per_mm;
  const double kx = (bx1 - bx0) / chart.width_mm, ky = (by1 - by0) / chart.height_mm;
  if (std::abs(kx - 1) > 0.05 || std::abs(ky - 1) > 0.05)
    return fail(ErrorCode::kPipeline, source.string() + ": the chart printed " + fmt(bx1 - bx0, 1) + " x " + fmt(by1 - by0, 1) +
                                          " mm, expected " + fmt(chart.width_mm, 1) + " x " + fmt(chart.height_mm, 1));
  // Try the four mirrorings; the orientation mark is where the fabric is darkest.
  Placement best;
  double darkest = 1e9;
  for (int flip = 0; flip < 4; ++flip) {
    Placement p;
    p.sx = flip & 1 ? -kx : kx;
    p.sy = flip & 2 ? -ky : ky;
    p.x0_mm = flip & 1 ? bx1 : bx0;
    p.y0_mm = flip & 2 ? by1 : by0;
    const int mx = static_cast<int>((p.x0_mm + p.sx * chart.mark_x_mm) * lab.px_per_mm);
    const int my = static_cast<int>((p.y0_mm + p.sy * chart.mark_y_mm) * lab.px_per_mm);
    if (mx < 0 || my < 0 || mx >= lab.width_px || my >= lab.height_px) continue;
    const double l = lab.at(mx, my)[0];
    if (l < darkest) {
      darkest = l;
      best = p;
    }
  }
  return best;
}

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
                         const std::optional<fs::path>& guide, const fs::path& log, double& area_m2) {
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
  auto chart = layout_chart(ti1->front(), base.string() + ".ti1");
  if (!chart) return fail(chart.error());
  // 2. Printed as a job, on the printer the job names (here: printsim through printctl run).
  if (auto st = write_chart_job(job, *chart, o); !st) return st;
  if (auto st = run_tool("chart job",
                         {(own_dir() / "printctl").string(), "run", job.string(), "--out", printed.string()}, log);
      !st)
    return st;
  area_m2 += chart->width_mm * chart->height_mm * 1e-6;
  // 3. Where it landed, then the simulated spectrophotometer reads every patch.
  auto lab = rip::read_image3f(printed / "fabric-lab.tif");
  if (!lab) return fail(ErrorCode::kPipeline, lab.error().message);
  auto where = locate_chart(*lab, *chart, printed / "fabric-lab.tif");
  if (!where) return fail(where.error());
  device::CgatsTable ti2;
  ti2.type = "CTI2";
  ti2.keywords = {{"DESCRIPTOR", "tp calibration chart as printed (patch centres on the fabric)"},
                  {"ORIGINATOR", "tp printctl calibrate"},
                  {"COLOR_REP", "RGB"}};
  ti2.fields = {"SAMPLE_ID", "RGB_R", "RGB_G", "RGB_B", "TP_X_MM", "TP_Y_MM"};
  for (const auto& p : chart->patches)
    ti2.rows.push_back({p.id, fmt(p.rgb_pct[0], 4), fmt(p.rgb_pct[1], 4), fmt(p.rgb_pct[2], 4),
                        fmt(where->x0_mm + where->sx * p.x_mm), fmt(where->y0_mm + where->sy * p.y_mm)});
  const fs::path ti2_path = base.string() + ".ti2";
  std::ofstream(ti2_path) << device::format_cgats(ti2);
  if (auto st = run_tool("measure",
                         {(own_dir() / "printsim").string(), "measure", "--chart", ti2_path.string(), "--fabric",
                          (printed / "fabric-lab.tif").string(), "--out", base.string() + ".ti3", "--aperture-mm",
                          fmt(o.aperture_mm, 2), "--noise", fmt(o.noise_de, 3)},
                         log);
      !st)
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

  if (o.measurements) {
    if (auto st = check_measurements(*o.measurements); !st) return fail(st.error());
    fs::copy_file(*o.measurements, base.string() + ".ti3", fs::copy_options::overwrite_existing, ec);
    if (ec) return fail(ErrorCode::kIo, base.string() + ".ti3: " + ec.message());
  } else {
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
                                      log, s.chart_area_m2);
          !st)
        return fail(st.error());
      readings.push_back(pass_base.string() + ".ti3");
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
            {"seconds", s.seconds}};
  std::ofstream(o.out / "calibration.json") << m.dump(2) << "\n";
  return s;
}

}  // namespace tp::host
