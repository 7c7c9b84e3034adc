// tests/scenarios/jobs/flat_pieces_test.cpp: a piece no stitch joins (a label) in a job sewn on a
// body is printed flat with a flat job's print, listed in the report and left out of the 3D garment.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/pattern/pattern_json.h"
#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"
#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The sample skirt (size M) with a 60 x 40 mm label that no stitch joins, as a native pattern.
geometry::Pattern skirt_with_label() {
  auto m = geometry::samples::parse_size("M");
  auto p = geometry::samples::draft_garment("skirt8", *m, "M");
  geometry::Piece label;
  label.name = "label";
  const geometry::Vec2 c[4] = {{0, 0}, {60, 0}, {60, 40}, {0, 40}};
  const char* names[4] = {"bottom", "right", "top", "left"};
  for (int i = 0; i < 4; ++i) {
    geometry::Edge e;
    e.name = names[i];
    e.points_mm = {c[i], c[(i + 1) % 4]};
    label.edges.push_back(e);
  }
  label.grain = geometry::GrainLine{{30, 5}, {30, 35}};
  p->pieces.push_back(label);
  return *p;
}

// A job package of that pattern: on the size M dress form, or flat (no body).
fs::path label_job(const fs::path& dir, bool body) {
  fs::create_directories(dir);
  if (auto st = geometry::save_pattern_json(skirt_with_label(), dir / "pattern.json"); !st)
    ADD_FAILURE() << st.error().message;
  json garment = {{"pattern", "pattern.json"}, {"mesh_edge", "25 mm"}, {"drape", false}};
  if (body) garment["body"] = {{"dress_form", json::object()}};
  json layer = {{"type", "planar"},
                {"procedural", {{"kind", "stripes"}, {"count", 4}, {"size_px", 256}}},
                {"centre", {"10 cm", "20 cm", 0}},
                {"width", "15 cm"},
                {"repeat", true}};
  json j = {{"format", "tp-job/1"},
            {"name", "skirt-label"},  // the same name: it is printed on the pieces
            {"garment", garment},
            {"design", {{"layers", json::array({layer})}}},
            {"marker", {{"fabric_width", "1.6 m"}, {"time_limit_s", 1}}},
            {"print", {{"dpi", 50}, {"preview_dpi", 20}}}};
  std::ofstream(dir / "job.json") << j.dump(2);
  return dir;
}

CommandResult run_job(const fs::path& job, const fs::path& out) {
  return run_command(
      {(bin_dir() / "printctl").string(), "run", job.string(), "--out", out.string(), "--printer", "none"});
}

TEST(FlatPieces, AnUnjoinedPieceIsPrintedFlatNestedAndCutButNotSewn) {
  const fs::path dir = scratch_dir("flat-pieces");
  auto r = run_job(label_job(dir / "job3d", true), dir / "out3d");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json rep = read_json(dir / "out3d/report.json");
  ASSERT_EQ(rep["state"], "done") << rep.value("error", "");
  const json& g = rep["garment"];
  EXPECT_EQ(g["mode"], "3d");
  ASSERT_EQ(g["flat_pieces"].size(), 1u) << g.dump(1);
  EXPECT_EQ(g["flat_pieces"][0]["piece"], "label");
  EXPECT_NE(g["flat_pieces"][0]["reason"].get<std::string>().find("no stitch joins it"), std::string::npos);
  EXPECT_EQ(g["checks"]["pass"], true) << g["checks"].dump(1);
  EXPECT_EQ(g["checks"]["unsewn_pieces"], json::array({"label"}));
  // One warning for the flat piece, not one from the stitches and another from the checks.
  int label_warnings = 0;
  for (const json& w : rep["warnings"]) label_warnings += w.get<std::string>().find("'label'") != std::string::npos;
  EXPECT_EQ(label_warnings, 1) << rep["warnings"].dump(1);
  // Not part of the 3D garment: its group in garment.obj has no faces.
  std::istringstream obj(read_text(dir / "out3d/garment.obj"));
  std::string line, group;
  int label_faces = 0, faces = 0;
  while (std::getline(obj, line)) {
    if (line.rfind("g ", 0) == 0) group = line.substr(2);
    if (line.rfind("f ", 0) == 0) ++faces, label_faces += group.find("label") != std::string::npos;
  }
  EXPECT_GT(faces, 100);
  EXPECT_EQ(label_faces, 0);
  // Nested, printed and cut like any piece.
  const auto pieces = rep["files"]["pieces"];
  EXPECT_NE(std::find(pieces.begin(), pieces.end(), json("pieces/label.png")), pieces.end()) << pieces.dump();
  EXPECT_NE(read_text(dir / "out3d/cut.svg").find("label"), std::string::npos);
  // Its print is the one the same job without a body gives it.
  auto f = run_job(label_job(dir / "jobflat", false), dir / "outflat");
  ASSERT_EQ(f.exit_code, 0) << f.output;
  EXPECT_EQ(read_text(dir / "out3d/pieces/label.png"), read_text(dir / "outflat/pieces/label.png"));
  // The sewn pieces' print comes from the garment on the body.
  EXPECT_NE(read_text(dir / "out3d/pieces/gore_1.png"), read_text(dir / "outflat/pieces/gore_1.png"));
}

}  // namespace
}  // namespace tp::test
