// tests/scenarios/jobs/roll_frame_slow_test.cpp: the carriage origin and the sublimation option
// end to end: a printer whose carriage starts over the right selvedge lays the same fabric, and a
// sublimation job lays its mirror image (docs/roll-frame.md).
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

// Mean grey of each cell of a cols x rows grid over the image, optionally read right to left.
std::vector<double> cells(const fs::path& file, int cols, int rows, bool reversed) {
  OIIO::ImageBuf buf(file.string());
  EXPECT_TRUE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << file;
  const OIIO::ImageSpec& s = buf.spec();
  std::vector<double> sum(static_cast<size_t>(cols) * rows, 0), n(sum.size(), 0);
  std::vector<float> px(static_cast<size_t>(s.nchannels));
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      buf.getpixel(x, y, px.data(), s.nchannels);
      const int cx = (reversed ? s.width - 1 - x : x) * cols / s.width;
      const size_t c = static_cast<size_t>(y * rows / s.height) * cols + static_cast<size_t>(cx);
      sum[c] += 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2];
      n[c] += 1;
    }
  for (size_t i = 0; i < sum.size(); ++i) sum[i] /= std::max(1.0, n[i]);
  return sum;
}

double mean_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d += std::abs(a[i] - b[i]);
  return d / static_cast<double>(a.size());
}

// Runs the flat example with `edit` applied to its job.json; returns the output folder.
fs::path run_job(const std::string& name, const std::function<void(const fs::path&, json&)>& edit) {
  const fs::path job = scratch_dir(name) / "job";
  fs::copy(source_dir() / "examples/shirt-front-flat", job, fs::copy_options::recursive);
  json j = read_json(job / "job.json");
  edit(job, j);
  std::ofstream(job / "job.json") << j.dump(2);
  const fs::path out = job.parent_path() / "out";
  auto r = run_command({(bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return out;
}

// Mean grey difference per 10 mm cell below which the fabric shows the marker itself. The fabric
// is the colorimetric printer's colour and the marker the design's sRGB, so even the right image
// differs by about 0.04 (0.0402 seen once); the mirror image differs by 0.15 or more.
constexpr double kSameImage = 0.07;

// Fabric against marker (the roll frame), as printed and read right to left: {same, mirrored}.
std::pair<double, double> fabric_vs_marker(const fs::path& out) {
  const json rep = read_json(out / "report.json");
  const int cols = static_cast<int>(rep["marker"]["fabric_width_mm"].get<double>() / 10);
  const int rows = static_cast<int>(rep["marker"]["length_mm"].get<double>() / 10);
  const auto marker = cells(out / "marker.png", cols, rows, false);
  return {mean_difference(cells(out / "fabric.png", cols, rows, false), marker),
          mean_difference(cells(out / "fabric.png", cols, rows, true), marker)};
}

TEST(RollFrameOptions, ACarriageStartingOnTheRightLaysTheSameFabric) {
  const fs::path out = run_job("origin_right", [](const fs::path& job, json& j) {
    auto model = run_command({(bin_dir() / "printsim").string(), "model"});
    ASSERT_EQ(model.exit_code, 0) << model.output;
    std::string text = model.output;
    const auto at = text.find("carriage_origin = left");
    ASSERT_NE(at, std::string::npos) << text;
    text.replace(at, std::string("carriage_origin = left").size(), "carriage_origin = right");
    std::ofstream(job / "right.tpm") << text;
    j["print"]["printer_model"] = "right.tpm";
  });
  const auto [same, mirrored] = fabric_vs_marker(out);
  std::printf("carriage origin right: fabric vs marker %.4f, vs its mirror %.4f\n", same, mirrored);
  EXPECT_LT(same, kSameImage);
  EXPECT_GT(mirrored, 2 * same);
}

TEST(RollFrameOptions, SublimationPrintsTheMirrorImage) {
  const fs::path out = run_job("sublimation", [](const fs::path&, json& j) { j["print"]["transfer"] = "sublimation"; });
  const auto [same, mirrored] = fabric_vs_marker(out);
  std::printf("sublimation: fabric vs marker %.4f, vs its mirror %.4f\n", same, mirrored);
  EXPECT_LT(mirrored, kSameImage);
  EXPECT_GT(same, 2 * mirrored);
  const json rep = read_json(out / "report.json");
  bool warned = false;
  for (const auto& w : rep["warnings"]) warned = warned || w.get<std::string>().find("sublimation") != std::string::npos;
  EXPECT_TRUE(warned) << rep["warnings"].dump();
}

}  // namespace
}  // namespace tp::test
