// tests/scenarios/jobs/garment_obj_slow_test.cpp: a 3D job's garment.obj opened by assimp (an
// independent reader): its material's diffuse map is garment.png, every piece is textured, the UVs
// lie in [0, 1], the units are stated; the report names the files, the units and the texture. Then
// three.js in headless Chromium (readers/check_garment_viewer.py) shows the garment with the print.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::map<std::string, std::string> facts(const std::string& output) {
  std::map<std::string, std::string> out;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (auto eq = line.find('='); eq != std::string::npos) out[line.substr(0, eq)] = line.substr(eq + 1);
  return out;
}

TEST(GarmentObj, AssimpOpensTheGarmentWithItsPrintAsTextureAndUvsInTheUnitSquare) {
  ASSERT_EQ(run_command({"sh", "-c", "command -v assimp"}).exit_code, 0)
      << "assimp missing (scripts/lib.sh TP_PACKAGES installs assimp-utils)";
  // The skirt example without a printer: the garment stage and the outputs are what matter here.
  const fs::path job = scratch_dir("garment_obj") / "job";
  fs::create_directories(job);
  json j = read_json(source_dir() / "examples/skirt-marbling/job.json");
  j["marker"]["time_limit_s"] = 1;
  j["garment"]["drape"] = false;  // garment.obj is the sewn garment; the drape gives previews only
  std::ofstream(job / "job.json") << j.dump(2);
  const fs::path out = job.parent_path() / "out";
  auto r = run_command(
      {(bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string(), "--printer", "none"});
  ASSERT_EQ(r.exit_code, 0) << r.output;

  auto a = run_command({"/usr/bin/python3", (source_dir() / "tests/scenarios/jobs/readers/check_garment_obj.py").string(),
                        (out / "garment.obj").string()});
  ASSERT_EQ(a.exit_code, 0) << a.output;
  auto f = facts(a.output);
  EXPECT_EQ(f["assimp_exit"], "0");
  EXPECT_GT(std::stoi(f["meshes"]), 0) << a.output;
  EXPECT_EQ(f["textured_meshes"], f["meshes"]) << "every piece carries the print material";
  EXPECT_EQ(f["textures"], "garment.png");
  EXPECT_GT(std::stoi(f["uv_count"]), 0);
  EXPECT_GE(std::stod(f["uv_min"]), 0.0);
  EXPECT_LE(std::stod(f["uv_max"]), 1.0);
  EXPECT_EQ(f["units_comment"], "yes");
  std::printf("assimp: %s meshes, %s faces, uv %s..%s, texture %s\n", f["meshes"].c_str(), f["faces"].c_str(),
              f["uv_min"].c_str(), f["uv_max"].c_str(), f["textures"].c_str());

  // A browser viewer: three.js's OBJLoader and MTLLoader in headless Chromium, served on loopback.
  // The screenshot shows the texture's colours on the garment, not a blank page or untextured grey.
  ASSERT_EQ(run_command({"sh", "-c", "command -v chromium && command -v chromedriver"}).exit_code, 0)
      << "chromium missing (scripts/lib.sh TP_PACKAGES installs chromium, chromium-driver, python3-selenium, libjs-three)";
  auto b = run_command({"/usr/bin/python3", (source_dir() / "tests/scenarios/jobs/readers/check_garment_viewer.py").string(),
                        out.string(), (out / "garment-viewer.png").string()});
  ASSERT_EQ(b.exit_code, 0) << b.output;
  auto bf = facts(b.output);
  EXPECT_EQ(bf["viewer_title"], "ready meshes=" + f["meshes"] + " textured=" + f["meshes"]) << b.output;
  EXPECT_EQ(bf["console_errors"], "0") << b.output;
  EXPECT_EQ(bf["shows_print"], "yes") << b.output;
  std::printf("browser: garment %s of the view, %s colours, hue overlap with garment.png %s\n",
              bf["garment_share"].c_str(), bf["distinct_colours"].c_str(), bf["hue_overlap"].c_str());

  // The texture is a valid PNG at the resolution the report gives.
  const json rep = read_json(out / "report.json");
  const json& files = rep["garment"]["files"];
  EXPECT_EQ(files["obj"], "garment.obj");
  EXPECT_EQ(files["mtl"], "garment.mtl");
  EXPECT_EQ(files["texture"], "garment.png");
  EXPECT_EQ(files["obj_units"], "mm");
  ASSERT_TRUE(files["texture_dpi"].is_number());
  auto png = run_command({"pngcheck", "-v", (out / "garment.png").string()});
  EXPECT_EQ(png.exit_code, 0) << png.output;
  EXPECT_NE(png.output.find("chunk pHYs"), std::string::npos) << png.output;
  EXPECT_LE(files["texture_width_px"].get<int>(), 4096);
  EXPECT_LE(files["texture_height_px"].get<int>(), 4096);
  // The garment wearing its print, front, side and back: valid PNGs.
  ASSERT_EQ(files["print_previews"].size(), 3u);
  for (const auto& name : files["print_previews"]) {
    auto pv = run_command({"pngcheck", (out / name.get<std::string>()).string()});
    EXPECT_EQ(pv.exit_code, 0) << pv.output;
  }

  // The 3D job's report against the schema as well.
  auto v = run_command({"/usr/bin/python3", "-c",
                        "import json, sys, jsonschema\n"
                        "schema = json.load(open(sys.argv[2]))\n"
                        "errors = list(jsonschema.Draft202012Validator(schema).iter_errors(json.load(open(sys.argv[1]))))\n"
                        "for e in errors: print('/'.join(map(str, e.absolute_path)) + ': ' + e.message)\n"
                        "sys.exit(1 if errors else 0)\n",
                        (out / "report.json").string(), (source_dir() / "docs/schema/report.schema.json").string()});
  EXPECT_EQ(v.exit_code, 0) << v.output;
}

}  // namespace
}  // namespace tp::test
