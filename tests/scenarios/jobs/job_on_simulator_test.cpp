// tests/scenarios/jobs/job_on_simulator_test.cpp: whole jobs through `printctl run` under printsim
// (real libusb and libgpiod code against the emulated printer): the printer lays what the RIP
// planned, and a job that cannot be made fails before anything reaches the printer.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Mean grey level (0..1) of each cell of a cols x rows grid laid over the whole image.
std::vector<double> cell_means(const fs::path& file, int cols, int rows) {
  OIIO::ImageBuf buf(file.string());
  EXPECT_TRUE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << file;
  const OIIO::ImageSpec& s = buf.spec();
  std::vector<double> sum(static_cast<size_t>(cols) * rows, 0), n(sum.size(), 0);
  std::vector<float> px(s.nchannels);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      buf.getpixel(x, y, px.data(), s.nchannels);
      const double grey = s.nchannels >= 3 ? 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2] : px[0];
      const size_t c = static_cast<size_t>(y * rows / s.height) * cols + static_cast<size_t>(x * cols / s.width);
      sum[c] += grey;
      n[c] += 1;
    }
  for (size_t i = 0; i < sum.size(); ++i) sum[i] /= std::max(1.0, n[i]);
  return sum;
}

TEST(JobOnSimulator, TheFabricShowsTheMarkerAndEverySwathAndCueArrived) {
  const fs::path out = scratch_dir("flat") / "out";
  auto r = run_command({(bin_dir() / "printctl").string(), "run", (source_dir() / "examples/shirt-front-flat").string(),
                        "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json rep = read_json(out / "report.json");
  EXPECT_EQ(rep["state"], "done");
  const json& p = rep["print"];
  EXPECT_EQ(p["outcome"], "completed");
  EXPECT_GT(p["swaths_total"].get<int>(), 0);
  EXPECT_EQ(p["swaths_sent"], p["swaths_total"]);
  EXPECT_EQ(p["swaths_acked"], p["swaths_total"]);
  EXPECT_EQ(p["printer_swaths_printed"], p["swaths_total"]);
  // Every drop the screen made reached the printer: its counters equal the RIP's, ink by ink.
  EXPECT_EQ(p["drops_per_ink"], rep["rip"]["drops_per_ink"]);
  ASSERT_FALSE(p["cues"].empty());
  for (const json& cue : p["cues"]) EXPECT_TRUE(cue["fired"].get<bool>()) << cue.dump();
  EXPECT_EQ(p["cues_fired"].get<size_t>(), p["cues"].size());
  // Fabric fed at least the marker's length.
  EXPECT_GE(p["feed_travel_mm"].get<double>(), rep["marker"]["length_mm"].get<double>() - 1.0);

  // The fabric, in cells of about 1 cm, shows the marker: same light and dark cells. The fabric
  // is drops through the simulator's ink model, the marker the contone plan, so a budget.
  const double width_mm = rep["marker"]["fabric_width_mm"], length_mm = rep["marker"]["length_mm"];
  const int cols = static_cast<int>(width_mm / 10), rows = static_cast<int>(length_mm / 10);
  auto fabric = cell_means(out / "fabric.png", cols, rows), marker = cell_means(out / "marker.png", cols, rows);
  double sum = 0, worst = 0;
  int blank_disagree = 0;
  for (size_t i = 0; i < fabric.size(); ++i) {
    const double d = std::abs(fabric[i] - marker[i]);
    sum += d;
    worst = std::max(worst, d);
    if ((marker[i] > 0.995) != (fabric[i] > 0.995)) ++blank_disagree;
  }
  const double mean = sum / fabric.size();
  RecordProperty("fabric_vs_marker_mean", std::to_string(mean));
  // 0.040 measured on the flat example since fabric.png shows the printer's colorimetric fabric
  // (its white and ink tones), not the sRGB plan's; 0.022 before.
  EXPECT_LT(mean, 0.05) << "worst cell " << worst;
  EXPECT_LT(worst, 0.25);
  EXPECT_LT(blank_disagree, static_cast<int>(fabric.size() / 100)) << "cells blank on one and printed on the other";
}

TEST(JobOnSimulator, AJobThatCannotBeMadeFailsBeforeAnythingIsPrinted) {
  const fs::path dir = scratch_dir("broken");
  const fs::path job = dir / "job";
  fs::copy(source_dir() / "examples/shirt-front-flat", job, fs::copy_options::recursive);
  // A design image that is not an image: the manifest is valid, the asset is not.
  std::ofstream(job / "motif.png") << "\x89PNG\r\n\x1a\n not really";
  json j = read_json(job / "job.json");
  j["design"]["layers"][1].erase("procedural");
  j["design"]["layers"][1]["image"] = "motif.png";
  std::ofstream(job / "job.json") << j.dump(2);

  auto v = run_command({(bin_dir() / "printctl").string(), "validate", job.string()});
  EXPECT_EQ(v.exit_code, 0) << v.output;  // the package itself is well formed

  const fs::path out = dir / "out";
  auto r = run_command({(bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("/design/layers/1/image"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("motif.png"), std::string::npos) << r.output;
  const json rep = read_json(out / "report.json");
  EXPECT_EQ(rep["state"], "failed");
  EXPECT_EQ(rep.value("error", "").rfind("design: ", 0), 0u) << rep.dump();
  for (const json& s : rep.value("stages", json::array())) {
    if (s["stage"] == "design") {
      EXPECT_EQ(s["state"], "failed");
    } else if (s["stage"] == "print") {
      EXPECT_NE(s["state"], "done");
    }
  }
  EXPECT_FALSE(rep.contains("print"));
  EXPECT_FALSE(fs::exists(out / "fabric.png"));
}

TEST(JobOnSimulator, AnInvalidPackageNamesTheFileAndField) {
  const fs::path job = scratch_dir("invalid") / "job";
  fs::copy(source_dir() / "examples/shirt-front-flat", job, fs::copy_options::recursive);
  json j = read_json(job / "job.json");
  j["finishing"]["seam_allowance"] = "1 furlong";
  j["garment"]["pattern"] = "../outside.json";
  std::ofstream(job / "job.json") << j.dump(2);
  auto v = run_command({(bin_dir() / "printctl").string(), "validate", job.string()});
  EXPECT_NE(v.exit_code, 0);
  EXPECT_NE(v.output.find("job.json"), std::string::npos) << v.output;
  EXPECT_NE(v.output.find("/finishing/seam_allowance"), std::string::npos) << v.output;
  EXPECT_NE(v.output.find("/garment/pattern"), std::string::npos) << v.output;
}

}  // namespace
}  // namespace tp::test
