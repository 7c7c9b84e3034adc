// tests/scenarios/jobs/output_readers_test.cpp: a printed job's output files opened by independent
// readers (ezdxf, pngcheck, rsvg-convert, tiffinfo): each reads what the file means.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/scenarios/jobs/report_schema.h"
#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

/// key=value lines of a reader's output.
std::map<std::string, std::string> facts(const std::string& output) {
  std::map<std::string, std::string> out;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (auto eq = line.find('='); eq != std::string::npos) out[line.substr(0, eq)] = line.substr(eq + 1);
  return out;
}

bool have(const std::string& tool) { return run_command({"sh", "-c", "command -v " + tool}).exit_code == 0; }

class OutputReaders : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = new fs::path(scratch_dir("output_readers") / "out");
    auto r = run_command({(bin_dir() / "printctl").string(), "run", (source_dir() / "examples/shirt-front-flat").string(),
                          "--out", out_->string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() { delete out_; }
  static fs::path* out_;
};
fs::path* OutputReaders::out_ = nullptr;

TEST_F(OutputReaders, EzdxfReadsTheCutFileAsR12WithAamaTextPointDrillsAndAnnotationOnTheRoll) {
  ASSERT_TRUE(run_command({"/usr/bin/python3", "-c", "import ezdxf"}).exit_code == 0)
      << "python3-ezdxf missing (scripts/lib.sh TP_PACKAGES installs it)";
  auto r = run_command({"/usr/bin/python3", (source_dir() / "tests/scenarios/jobs/readers/check_cut_dxf.py").string(),
                        (*out_ / "cut.dxf").string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto f = facts(r.output);
  EXPECT_EQ(f["version"], "AC1009");
  EXPECT_EQ(f["audit_errors"], "0");
  EXPECT_EQ(f["insunits"], "no");  // an R2000 variable
  EXPECT_EQ(f["ltype_continuous"], "yes");
  for (const char* layer : {"1", "4", "7", "8", "13", "14", "15"}) EXPECT_EQ(f[std::string("layer_") + layer], "yes") << layer;
  EXPECT_EQ(f["entities_loaded"], f["entities_written"]);
  RecordProperty("ezdxf_entities", f["entities_loaded"] + "/" + f["entities_written"]);
  std::printf("ezdxf accepted %s of %s entities\n", f["entities_loaded"].c_str(), f["entities_written"].c_str());
  EXPECT_TRUE(f["drill_kinds"].empty() || f["drill_kinds"] == "POINT") << f["drill_kinds"];
  EXPECT_EQ(f["style_units"], "yes");
  EXPECT_EQ(f["style_name"], "yes");
  // Everything drawn, texts included, lies within the roll the header's extents give.
  double ex0, ey0, ex1, ey1, hx0, hy0, hx1, hy1;
  ASSERT_EQ(std::sscanf(f["extents"].c_str(), "%lf,%lf,%lf,%lf", &ex0, &ey0, &ex1, &ey1), 4) << r.output;
  ASSERT_EQ(std::sscanf(f["header_extmin"].c_str(), "%lf,%lf", &hx0, &hy0), 2);
  ASSERT_EQ(std::sscanf(f["header_extmax"].c_str(), "%lf,%lf", &hx1, &hy1), 2);
  EXPECT_EQ(hx0, 0);
  EXPECT_EQ(hy0, 0);
  EXPECT_GE(ex0, hx0);
  EXPECT_GE(ey0, hy0);
  EXPECT_LE(ex1, hx1);
  EXPECT_LE(ey1, hy1);
  // The roll along DXF X: the header's X extent is the marker length.
  const auto report = read_json(*out_ / "report.json");
  EXPECT_NEAR(hx1, report["marker"]["length_mm"].get<double>(), 0.01);
  EXPECT_NEAR(hy1, report["marker"]["fabric_width_mm"].get<double>(), 0.01);
}

TEST_F(OutputReaders, PngcheckFindsEveryPngValidWithItsResolution) {
  ASSERT_TRUE(have("pngcheck")) << "pngcheck missing (scripts/lib.sh TP_PACKAGES installs it)";
  // preview_dpi 40 in the example; the fabric preview is the print's 150 dpi halved.
  std::vector<std::pair<fs::path, std::string>> files = {{*out_ / "marker.png", "(40 dpi)"},
                                                         {*out_ / "fabric.png", "(75 dpi)"}};
  for (const auto& e : fs::directory_iterator(*out_ / "pieces")) files.push_back({e.path(), "(40 dpi)"});
  for (const auto& [file, dpi] : files) {
    auto r = run_command({"pngcheck", "-v", file.string()});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("chunk pHYs"), std::string::npos) << file << "\n" << r.output;
    EXPECT_NE(r.output.find(dpi), std::string::npos) << file << "\n" << r.output;
  }
}

TEST_F(OutputReaders, RsvgConvertRendersTheCutLayerAlone) {
  ASSERT_TRUE(have("rsvg-convert")) << "librsvg2-bin missing (scripts/lib.sh TP_PACKAGES installs it)";
  const fs::path all = *out_ / "cut-all.png", cut = *out_ / "cut-layer.png";
  auto r = run_command({"rsvg-convert", "-f", "png", "-o", all.string(), (*out_ / "cut.svg").string()});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // A cutter's import selects the cut layer by its id; rsvg-convert renders just that group.
  for (const char* layer : {"cut", "notch", "drill", "grain", "annotation", "roll"}) {
    auto one = run_command({"rsvg-convert", "-f", "png", "-i", layer, "-o", cut.string(), (*out_ / "cut.svg").string()});
    EXPECT_EQ(one.exit_code, 0) << layer << ": " << one.output;
  }
  auto missing = run_command({"rsvg-convert", "-f", "png", "-i", "no-such-layer", "-o", cut.string(),
                              (*out_ / "cut.svg").string()});
  EXPECT_NE(missing.exit_code, 0) << "rsvg-convert accepts any id: the check above proves nothing";
}

TEST_F(OutputReaders, TiffinfoSeesInkChannelsAtThePrintResolutionWithoutAlpha) {
  ASSERT_TRUE(have("tiffinfo")) << "libtiff-tools missing (scripts/lib.sh TP_PACKAGES installs it)";
  auto r = run_command({"tiffinfo", (*out_ / "fabric.tif").string()});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Resolution: 150, 150 pixels/inch"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Samples/Pixel: 4"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("assoc-alpha"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("Extra Samples"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Photometric Interpretation: separated"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("InkSet: 1"), std::string::npos) << r.output;  // 1: CMYK
  EXPECT_NE(r.output.find("Ink Names: cyan, magenta, yellow, black"), std::string::npos) << r.output;
}

TEST_F(OutputReaders, TheReportMatchesItsSchema) {
  ASSERT_EQ(run_command({"/usr/bin/python3", "-c", "import jsonschema"}).exit_code, 0)
      << "python3-jsonschema missing (scripts/lib.sh TP_PACKAGES installs it)";
  auto done = validate_report(*out_ / "report.json");
  EXPECT_EQ(done.exit_code, 0) << done.output;
  const auto rep = read_json(*out_ / "report.json");
  EXPECT_EQ(rep["schema"], "tp-report/1");
  EXPECT_TRUE(rep["warnings"].is_array());
  for (const char* ink : {"cyan", "magenta", "yellow", "black"}) {
    EXPECT_GT(rep["ink"]["ml"][ink].get<double>(), 0) << ink;
    EXPECT_GT(rep["ink"]["drops"][ink].get<std::uint64_t>(), 0u) << ink;
  }
  const double est = rep["estimate"]["print_time_s"], meas = rep["measured"]["print_time_s"];
  std::printf("print time estimated %.2f s, measured %.2f s\n", est, meas);
  RecordProperty("print_time_estimated_s", std::to_string(est));
  RecordProperty("print_time_measured_s", std::to_string(meas));
  EXPECT_GT(est, 0.5 * meas);
  EXPECT_LT(est, 2 * meas);
  EXPECT_NEAR(rep["measured"]["fabric_length_mm"].get<double>(), rep["estimate"]["fabric_length_mm"].get<double>(), 1);

  // A job that fails in its design stage still writes a report of the same schema.
  const fs::path job = scratch_dir("report_failed") / "job";
  fs::copy(source_dir() / "examples/shirt-front-flat", job, fs::copy_options::recursive);
  std::ofstream(job / "motif.png") << "not an image";
  auto j = read_json(job / "job.json");
  j["design"]["layers"][1].erase("procedural");
  j["design"]["layers"][1]["image"] = "motif.png";
  std::ofstream(job / "job.json") << j.dump(2);
  const fs::path out = job.parent_path() / "out";
  auto r = run_command({(bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string()});
  EXPECT_NE(r.exit_code, 0);
  auto failed = validate_report(out / "report.json");
  EXPECT_EQ(failed.exit_code, 0) << failed.output;
}

}  // namespace
}  // namespace tp::test
