// host/calibration/internal/chart_print.cpp: a calibration chart as a flat job (one rectangular
// piece carrying the chart picture), printed, located on the fabric and measured.
#include "host/calibration/internal/chart_print.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "device/model/printer_model_file.h"
#include "host/calibration/chart_layout.h"
#include "host/job/printer_choice.h"
#include "rip/colour/lab_image.h"
#include "rip/image/image_io.h"

extern char** environ;

namespace tp::host::internal {

namespace fs = std::filesystem;
using nlohmann::json;

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

std::string fmt(double v, int decimals) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

namespace {

constexpr double kChartAllowanceMm = 1;  ///< the chart piece's seam and hem allowance
constexpr double kMinFrameInk = 8;       ///< CIELAB distance from the fabric a frame pixel has at least

// The flat job that prints the chart: one rectangular piece carrying the chart picture.
Status write_chart_job(const fs::path& dir, const ChartLayout& chart, const CalibrateOptions& o,
                       const ChartJobExtras& extras) {
  fs::create_directories(dir);
  if (auto s = rip::write_png(dir / "chart.png", chart.image, rip::PngChannels::kRgba, chart.geometry.px_per_mm * 25.4);
      !s)
    return fail(ErrorCode::kIo, "chart picture: " + s.error().message);
  const double w = chart.width_mm, h = chart.height_mm;
  json piece = {
      {"name", "chart"},
      {"edges", json::array({json{{"name", "top"}, {"from", {0.0, 0.0}}}, json{{"name", "right"}, {"from", {w, 0.0}}},
                             json{{"name", "bottom"}, {"from", {w, h}}}, json{{"name", "left"}, {"from", {0.0, h}}}})}};
  json pattern = {{"format", "tp-pattern"},
                  {"version", 1},
                  {"name", "calibration_chart"},
                  {"units", "mm"},
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
  json job = {
      {"format", "tp-job/1"},
      {"name", "calibration-chart"},
      {"garment", {{"pattern", "pattern.json"}}},
      {"design",
       {{"layers", json::array({json{{"type", "planar"},
                                     {"name", "chart"},
                                     {"image", "chart.png"},
                                     {"centre", {w / 2, h / 2, 0.0}},
                                     {"normal", {0, 0, 1}},
                                     {"up", {0, 1, 0}},
                                     {"width", std::to_string(w) + " mm"}}})}}},
      {"finishing",
       {{"seam_allowance", fmt(kChartAllowanceMm, 1) + " mm"},
        {"hem_allowance", fmt(kChartAllowanceMm, 1) + " mm"},
        {"notches", false},
        {"labels", "none"}}},
      {"marker",
       {{"fabric_width", std::to_string(std::ceil(w + 60)) + " mm"}, {"rotations", "fixed"}, {"time_limit_s", 1}}},
      {"print",
       {{"printer", std::string(to_string(PrinterChoice::kSim))},
        {"printer_model", "printer.tpm"},
        {"dpi", o.dpi},
        {"passes", 1},
        {"preview_dpi", 40}}}};
  if (!extras.device_inks.empty()) job["print"]["device_inks"] = extras.device_inks;
  if (extras.calibration) {
    // The set travels inside the chart's package, as a job's assets do.
    std::error_code ec;
    fs::copy_file(*extras.calibration, dir / "calibration.json", fs::copy_options::overwrite_existing, ec);
    if (ec) return fail(ErrorCode::kIo, (dir / "calibration.json").string() + ": " + ec.message());
    job["print"]["calibration"] = "calibration.json";
  }
  std::ofstream(dir / "job.json") << job.dump(1) << "\n";
  return {};
}

// Where the chart landed: the black frame's bounding box, and which way round (the mark's corner).
struct Placement {
  double x0_mm = 0, y0_mm = 0, sx = 1, sy = 1;  // fabric = origin + scale * chart (negative: flipped)
};

Result<Placement> locate_chart(const rip::Image3f& lab, const ChartLayout& chart, const fs::path& source) {
  // The bare fabric: the roll's last column (the chart job's roll is 60 mm wider than the chart).
  double white[3] = {0, 0, 0};
  for (int y = 0; y < lab.height_px; ++y)
    for (int c = 0; c < 3; ++c) white[c] += lab.at(lab.width_px - 1, y)[c] / std::max(1, lab.height_px);
  auto ink = [&](int x, int y) {
    const auto& v = lab.at(x, y);
    return std::hypot(v[0] - white[0], v[1] - white[1], v[2] - white[2]);
  };
  // The frame is the chart's heaviest ink (black in RGB; the inks a device-value chart drives):
  // everything at least half as far from the fabric as the farthest pixel lies inside it.
  double farthest = 0;
  for (int y = 0; y < lab.height_px; ++y)
    for (int x = 0; x < lab.width_px; ++x) farthest = std::max(farthest, ink(x, y));
  const double threshold = std::max(kMinFrameInk, 0.5 * farthest);
  int x0 = lab.width_px, y0 = lab.height_px, x1 = -1, y1 = -1;
  for (int y = 0; y < lab.height_px; ++y)
    for (int x = 0; x < lab.width_px; ++x)
      if (ink(x, y) > threshold) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
  if (x1 < 0) return fail(ErrorCode::kPipeline, source.string() + ": the chart's frame is not on the fabric");
  // The piece's allowance carries the frame's ink too (an allowance prints its edge's design).
  const double bx0 = x0 / lab.px_per_mm + kChartAllowanceMm, by0 = y0 / lab.px_per_mm + kChartAllowanceMm;
  const double bx1 = (x1 + 1) / lab.px_per_mm - kChartAllowanceMm, by1 = (y1 + 1) / lab.px_per_mm - kChartAllowanceMm;
  const double kx = (bx1 - bx0) / chart.width_mm, ky = (by1 - by0) / chart.height_mm;
  if (std::abs(kx - 1) > 0.05 || std::abs(ky - 1) > 0.05)
    return fail(ErrorCode::kPipeline, source.string() + ": the chart printed " + fmt(bx1 - bx0, 1) + " x " +
                                          fmt(by1 - by0, 1) + " mm, expected " + fmt(chart.width_mm, 1) + " x " +
                                          fmt(chart.height_mm, 1));
  // Try the four mirrorings; the orientation mark is where the fabric holds the most ink.
  Placement best;
  double darkest = -1;
  for (int flip = 0; flip < 4; ++flip) {
    Placement p;
    p.sx = flip & 1 ? -kx : kx;
    p.sy = flip & 2 ? -ky : ky;
    p.x0_mm = flip & 1 ? bx1 : bx0;
    p.y0_mm = flip & 2 ? by1 : by0;
    const int mx = static_cast<int>((p.x0_mm + p.sx * chart.mark_x_mm) * lab.px_per_mm);
    const int my = static_cast<int>((p.y0_mm + p.sy * chart.mark_y_mm) * lab.px_per_mm);
    if (mx < 0 || my < 0 || mx >= lab.width_px || my >= lab.height_px) continue;
    const double l = ink(mx, my);
    if (l > darkest) {
      darkest = l;
      best = p;
    }
  }
  return best;
}

}  // namespace

Status print_chart(const CalibrateOptions& o, const device::CgatsTable& ti1, const std::string& source,
                   const fs::path& base, const fs::path& job, const fs::path& printed, const ChartJobExtras& extras,
                   const fs::path& log, double& area_m2) {
  auto chart = layout_chart(ti1, source);
  if (!chart) return fail(chart.error());
  // Printed as a job, on the printer the job names (here: printsim through printctl run).
  if (auto st = write_chart_job(job, *chart, o, extras); !st) return st;
  if (auto st = run_tool("chart job " + job.filename().string(),
                         {(own_dir() / "printctl").string(), "run", job.string(), "--out", printed.string()}, log);
      !st)
    return st;
  area_m2 += chart->width_mm * chart->height_mm * 1e-6;
  // Where it landed, then the simulated spectrophotometer reads every patch.
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
  return run_tool("measure",
                  {(own_dir() / "printsim").string(), "measure", "--chart", ti2_path.string(), "--fabric",
                   (printed / "fabric-lab.tif").string(), "--out", base.string() + ".ti3", "--aperture-mm",
                   fmt(o.aperture_mm, 2), "--noise", fmt(o.noise_de, 3)},
                  log);
}

}  // namespace tp::host::internal
