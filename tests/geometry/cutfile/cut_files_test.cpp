// tests/geometry/cutfile/cut_files_test.cpp: cut jobs placed on the roll, DXF-AAMA and SVG text,
// and a round trip through the project's DXF-AAMA importer.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/cut_outline.h"
#include "geometry/cutfile/cut_job.h"
#include "geometry/cutfile/dxf_aama_writer.h"
#include "geometry/cutfile/svg_writer.h"
#include "geometry/pattern/import/dxf_aama.h"
#include "tests/geometry/design/test_garments.h"
#include "tests/support/paths.h"

namespace tp::geometry {
namespace {

Marker two_pieces_marker() {
  Marker m;
  m.width_mm = 1600;
  m.length_mm = 1200;
  PiecePlacement a;
  a.piece = 0;
  a.offset_mm = {300, 40};
  PiecePlacement b;
  b.piece = 1;
  b.rotation_deg = 180;
  b.mirrored = true;
  b.offset_mm = {900, 750};
  m.placements = {a, b};
  return m;
}

// Largest distance from any point of `a` to the polygon `b` (one-sided Hausdorff, vertices).
double max_distance(const Polygon& a, const Polygon& b) {
  double worst = 0;
  for (Vec2 p : a) {
    double best = 1e300;
    for (size_t i = 0; i < b.size(); ++i) {
      const Vec2 s = b[i], e = b[(i + 1) % b.size()], d = e - s;
      const double t = std::clamp(dot(p - s, d) / std::max(dot(d, d), 1e-300), 0.0, 1.0);
      best = std::min(best, norm(p - (s + d * t)));
    }
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(CutJob, PlacesEveryPieceAsOnTheRoll) {
  auto g = test::gore_skirt(4);
  Finishing f;
  f.job_name = "J7";
  auto job = make_cut_job(g.pattern, f, two_pieces_marker());
  ASSERT_TRUE(job) << job.error().what();
  ASSERT_EQ(job->pieces.size(), 2u);
  const PieceCut& b = job->pieces[1];
  // The placement maps the piece frame to the roll: turned face up (y -> -y), mirrored, then
  // turned half round.
  const Vec2 p = b.piece_to_roll.apply({10, 20});
  EXPECT_NEAR(p.x, 900 + 10, 1e-9);
  EXPECT_NEAR(p.y, 750 + 20, 1e-9);
  // The cut line is the allowance outline the renderer prints.
  auto a = resolve_allowance(g.pattern, 1, f);
  ASSERT_TRUE(a);
  auto cut = cut_outline(g.pattern.pieces[1], *a, f.mitre_limit);
  ASSERT_TRUE(cut);
  EXPECT_EQ(b.cut_line, *cut);
  EXPECT_FALSE(b.notch_lines.empty());
  EXPECT_EQ(b.grain.size(), 1u);
  EXPECT_NE(std::find(b.annotation.begin(), b.annotation.end(), "Piece Name: gore1"), b.annotation.end());
}

TEST(CutJob, RejectsAPlacementOfAMissingPiece) {
  auto g = test::gore_skirt(4);
  Marker m = two_pieces_marker();
  m.placements[1].piece = 9;
  auto job = make_cut_job(g.pattern, Finishing{}, m);
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("marker.placements[1].piece"), std::string::npos) << job.error().message;
}

TEST(DxfAama, RoundTripThroughTheImporterGivesBackTheContours) {
  auto g = test::gore_skirt(4);
  Finishing f;
  f.stitch_notch_type = NotchType::kSlit;
  auto job = make_cut_job(g.pattern, f, two_pieces_marker());
  ASSERT_TRUE(job) << job.error().what();
  const std::string text = dxf_aama_text(*job);
  auto back = read_dxf_aama(text, "cut.dxf");
  ASSERT_TRUE(back) << back.error().what();
  ASSERT_EQ(back->pieces.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const PieceCut& pc = job->pieces[i];
    const Piece* read = nullptr;
    for (const Piece& p : back->pieces)
      if (p.name == pc.name) read = &p;
    ASSERT_NE(read, nullptr) << pc.name;
    // With a sew line the importer's outline is the seam line; both ways within 0.01 mm.
    const Polygon seam = outline(*read);
    EXPECT_LT(max_distance(seam, pc.sew_line), 0.01) << pc.name;
    EXPECT_LT(max_distance(pc.sew_line, seam), 0.01) << pc.name;
    // Notches come back on the seam line at the positions written.
    EXPECT_EQ(read->notches.size(), pc.notch_lines.size()) << pc.name;
    ASSERT_TRUE(read->grain.has_value());
    EXPECT_LT(norm(read->grain->from_mm - pc.grain[0][0]) + norm(read->grain->to_mm - pc.grain[0][1]), 0.01);
  }
}

TEST(DxfAama, WithoutASewLineTheImporterReadsTheCutLine) {
  auto g = test::gore_skirt(4);
  Finishing f;
  auto job = make_cut_job(g.pattern, f, two_pieces_marker());
  ASSERT_TRUE(job);
  for (PieceCut& p : job->pieces) p.sew_line.clear();
  auto back = read_dxf_aama(dxf_aama_text(*job), "cut_only.dxf");
  ASSERT_TRUE(back) << back.error().what();
  ASSERT_EQ(back->pieces.size(), 2u);
  for (const PieceCut& pc : job->pieces) {
    for (const Piece& p : back->pieces) {
      if (p.name != pc.name) continue;
      const Polygon cut = outline(p);
      EXPECT_LT(max_distance(cut, pc.cut_line_notched), 0.01);
      EXPECT_LT(max_distance(pc.cut_line_notched, cut), 0.01);
    }
  }
}

TEST(DxfAama, InsertsCarryThePlacement) {
  auto g = test::gore_skirt(4);
  auto job = make_cut_job(g.pattern, Finishing{}, two_pieces_marker());
  ASSERT_TRUE(job);
  const std::string text = dxf_aama_text(*job);
  // The mirrored, half-turned piece, in the cutter's frame (DXF X along the roll): roll (900, 750)
  // is DXF (750, 900); face-up flip, mirror and half turn cancel, leaving the axis swap: an
  // x scale of -1 and a rotation of 270 degrees.
  EXPECT_NE(text.find("INSERT\n8\n0\n2\ngore1\n10\n750.0000\n20\n900.0000\n30\n0.0000\n41\n-1.0000\n42\n1.0000\n50\n270.0000"),
            std::string::npos);
  // R12 has no $INSUNITS: the units are AAMA text.
  EXPECT_EQ(text.find("$INSUNITS"), std::string::npos);
  EXPECT_NE(text.find("\n1\nUnits: METRIC\n"), std::string::npos);
}

TEST(Svg, DrawsEachPieceInMillimetresOnTheRoll) {
  auto g = test::gore_skirt(4);
  auto job = make_cut_job(g.pattern, Finishing{}, two_pieces_marker());
  ASSERT_TRUE(job);
  const std::string svg = svg_text(*job);
  EXPECT_NE(svg.find("width=\"1600.000mm\""), std::string::npos);
  // The view starts at the left selvedge; it grows along the roll to the pieces that overhang it.
  EXPECT_NE(svg.find("viewBox=\"0.000 "), std::string::npos);
  EXPECT_NE(svg.find("<rect x=\"0\" y=\"0\" width=\"1600.000\" height=\"1200.000\"/>"), std::string::npos);
  // One group per cutter layer; the cut layer holds each piece's cut line and nothing else.
  for (const char* layer : {"roll", "cut", "sew", "notch", "drill", "grain", "internal", "annotation"})
    EXPECT_NE(svg.find(std::string("<g id=\"") + layer + "\" inkscape:groupmode=\"layer\""), std::string::npos) << layer;
  const size_t cut_at = svg.find("<g id=\"cut\""), cut_end = svg.find("</g>", cut_at);
  const std::string cut_layer = svg.substr(cut_at, cut_end - cut_at);
  EXPECT_NE(cut_layer.find("id=\"cut-gore0\""), std::string::npos);
  EXPECT_EQ(cut_layer.find("<text"), std::string::npos);
  EXPECT_EQ(cut_layer.find("<rect"), std::string::npos);
  const auto dir = test::scratch_dir("cutfile_svg");
  ASSERT_TRUE(write_svg(*job, dir / "cut.svg"));
  ASSERT_TRUE(write_dxf_aama(*job, dir / "cut.dxf"));
  EXPECT_GT(std::filesystem::file_size(dir / "cut.dxf"), 1000u);
  auto bad = write_svg(*job, dir / "no_such_dir" / "cut.svg");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("cut.svg"), std::string::npos);
}

}  // namespace
}  // namespace tp::geometry
