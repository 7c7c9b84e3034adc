// tests/scenarios/jobs/order_on_simulator_slow_test.cpp: a small order (two sizes, three
// personalised copies) printed on printsim: one marker with every piece, size and copy in the cut
// files, the design re-projected onto the other size, each copy's own text in its pieces.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "rip/image/image_io.h"
#include "tests/scenarios/jobs/report_schema.h"
#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

const char* kOrderJob = R"({
  "format": "tp-job/1", "name": "small-order",
  "garment": {"sample": "simple_top", "size": "M", "drape": false},
  "design": {"layers": [
    {"type": "planar", "name": "bust motif", "procedural": {"kind": "motif", "size_px": 256},
     "centre": [0, 1213.5, 160], "normal": [0, 0, 1], "width": "10 cm"},
    {"type": "stroke", "name": "side sweep", "points": [[120, 1100, 110], [200, 1080, 0], [120, 1060, -110]],
     "radius": "8 mm", "colour": [200, 30, 60, 255]},
    {"type": "text", "name": "number", "text": "{number}", "size": "10 cm",
     "centre": [0, 1150, -200], "normal": [0, 0, -1], "colour": [20, 30, 90, 255]}
  ]},
  "order": {"sizes": [{"size": "S", "quantity": 2}, {"size": "M", "quantity": 1}], "base_size": "M",
            "copies": [{"number": 7}, {"number": 10}, {"number": 4}]},
  "marker": {"fabric_width": "1.4 m", "gap": "4 mm", "budget": {"iterations": 3000}},
  "print": {"printer": "sim", "dpi": 75, "preview_dpi": 20}
})";

// Pixels of a piece image close to an ink colour (default: the number's).
long ink_pixels(const fs::path& png, int r = 20, int g = 30, int b = 90) {
  auto img = rip::read_image(png);
  if (!img) return -1;
  long n = 0;
  for (const auto& p : img->pixels)
    n += p.a > 200 && std::abs(p.r - r) < 12 && std::abs(p.g - g) < 12 && std::abs(p.b - b) < 12;
  return n;
}

// Pixels of a lit 3D preview in the number's navy: bluish and dark, whatever the shading.
long navy_pixels(const fs::path& png) {
  auto img = rip::read_image(png);
  if (!img) return -1;
  long n = 0;
  for (const auto& p : img->pixels) n += p.a > 200 && p.b > p.r + 25 && p.b > p.g + 20 && p.r < 100 && p.b < 160;
  return n;
}

TEST(OrderOnSimulator, OneMarkerEveryPieceEachCopyItsOwnText) {
  const fs::path dir = scratch_dir("order_on_simulator");
  fs::create_directories(dir / "job");
  std::ofstream(dir / "job" / "job.json") << kOrderJob;
  const fs::path out = dir / "out";
  auto r = run_command({(bin_dir() / "printctl").string(), "run", (dir / "job").string(), "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto valid = validate_report(out / "report.json");
  EXPECT_EQ(valid.exit_code, 0) << valid.output;
  std::ifstream in(out / "report.json");
  const auto rep = nlohmann::json::parse(in);
  ASSERT_EQ(rep["state"], "done");

  // One marker holding all 3 x 4 pieces; the order's figures filled in after the marker and RIP.
  EXPECT_EQ(rep["piece_count"], 12);
  ASSERT_EQ(rep["marker"]["markers"].size(), 1u);
  EXPECT_EQ(rep["marker"]["markers"][0]["pieces"], 12);
  EXPECT_EQ(rep["order"]["garments"], 3);
  EXPECT_GT(rep["order"]["fabric_length_mm"].get<double>(), 0);
  EXPECT_GT(rep["order"]["utilisation"].get<double>(), 0.3);
  EXPECT_TRUE(rep["order"]["ink"].is_object());
  EXPECT_GT(rep["measured"]["fabric_length_mm"].get<double>(), 0);

  // Sizes and copies in the report and in the cut file's piece annotations.
  ASSERT_EQ(rep["sizes"].size(), 2u);
  ASSERT_EQ(rep["copies"].size(), 3u);
  std::ifstream dxf_in(out / "cut.dxf");
  std::stringstream dxf;
  dxf << dxf_in.rdbuf();
  for (const auto& c : rep["copies"]) {
    const std::string size = c["size"];
    EXPECT_EQ(c["pieces"].size(), 4u);
    for (const auto& p : c["pieces"]) {
      const std::string name = p;
      EXPECT_NE(name.find("." + size + "." + std::to_string(c["copy"].get<int>())), std::string::npos) << name;
      EXPECT_NE(dxf.str().find("Piece Name: " + name), std::string::npos) << name;
    }
  }
  EXPECT_EQ(rep["copies"][0]["texts"][0], "7");
  EXPECT_EQ(rep["copies"][1]["texts"][0], "10");
  EXPECT_EQ(rep["copies"][2]["size"], "M");

  // Re-projection onto S: the motif centre on S's bust point at the same offset, its size kept.
  const auto& s = rep["sizes"][0];
  ASSERT_EQ(s["size"], "S");
  EXPECT_EQ(s["reprojection"]["placement"], "body");
  const auto& motif = s["reprojection"]["layers"][0];
  EXPECT_LT(motif["landmark_error_mm"].get<double>(), 3.0);
  EXPECT_NEAR(motif["size_ratio"].get<double>(), 1.0, 0.005);
  EXPECT_LT(motif["centre_mm"][1].get<double>(), 1213.5 - 10);  // S's bust line is lower than M's
  EXPECT_TRUE(s["seams"].is_object());

  // Each copy's number is printed on its back pieces (and not on the fronts); copies differ.
  long back1 = 0, back2 = 0, front1 = 0;
  for (const char* piece : {"back_l", "back_r"}) {
    back1 += ink_pixels(out / "pieces" / (std::string(piece) + ".S.1.png"));
    back2 += ink_pixels(out / "pieces" / (std::string(piece) + ".S.2.png"));
  }
  for (const char* piece : {"front_l", "front_r"})
    front1 += ink_pixels(out / "pieces" / (std::string(piece) + ".S.1.png"));
  EXPECT_GT(back1, 50);
  EXPECT_GT(back2, 50);
  EXPECT_NE(back1, back2);  // "7" and "10" do not ink the same area
  EXPECT_EQ(front1, 0);

  // Each size's print previews show its first copy on that size's own body (not copy 1, size S,
  // inside the base size's body with the other copies beside it): S's number is seen from the
  // back, and the job's own previews are the base size's.
  for (const auto& sz : rep["sizes"]) {
    ASSERT_EQ(sz["print_previews"].size(), 3u) << sz.dump();
    for (const auto& f : sz["print_previews"]) EXPECT_TRUE(fs::is_regular_file(out / f.get<std::string>())) << f;
  }
  const long navy_s = navy_pixels(out / "sizes" / "S" / "garment-print-back.png");
  const long navy_m = navy_pixels(out / "sizes" / "M" / "garment-print-back.png");
  std::printf("figure order_preview_navy_pixels S_back=%ld M_back=%ld\n", navy_s, navy_m);
  EXPECT_GT(navy_s, 200);
  EXPECT_GT(navy_m, 200);
  ASSERT_EQ(rep["garment"]["files"]["print_previews"].size(), 3u);
  EXPECT_EQ(read_text(out / "garment-print-back.png"), read_text(out / "sizes" / "M" / "garment-print-back.png"));

  // The side sweep crosses the left side seam in every size: inked on the left front and back.
  for (const char* copy : {"S.1", "M.3"}) {
    EXPECT_GT(ink_pixels(out / "pieces" / ("front_l." + std::string(copy) + ".png"), 200, 30, 60), 20) << copy;
    EXPECT_GT(ink_pixels(out / "pieces" / ("back_l." + std::string(copy) + ".png"), 200, 30, 60), 20) << copy;
    EXPECT_EQ(ink_pixels(out / "pieces" / ("front_r." + std::string(copy) + ".png"), 200, 30, 60), 0) << copy;
  }
}

}  // namespace
}  // namespace tp::test
