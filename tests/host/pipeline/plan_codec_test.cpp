// tests/host/pipeline/plan_codec_test.cpp: plan files round-trip bit for bit and bad ones are
// refused naming the file and the place.
#include <gtest/gtest.h>

#include <cstring>

#include "host/pipeline/internal/input_hash.h"
#include "host/pipeline/internal/plan_codec.h"

namespace tp::host::internal {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

geometry::Garment awkward_garment() {
  geometry::Garment g;
  g.vertices_mm = {{0.1, 1.0 / 3.0, -2.5e-300}, {123456.78901234567, -0.0, 7}, {1e-7, 2, 3}};
  geometry::GarmentPiece p;
  p.piece = 0;
  p.mesh.vertices_mm = {{0.1, 0.2}, {std::nextafter(1.0, 2.0), 0}, {0, 1.0 / 7.0}};
  p.mesh.triangles = {{0, 1, 2}};
  p.mesh.edge_vertices = {{0, 1}, {1, 2}, {2, 0}};
  p.vertex_3d = {0, 1, 2};
  g.pieces.push_back(p);
  return g;
}

TEST(PlanCodec, AGarmentRoundTripsBitForBit) {
  const geometry::Garment g = awkward_garment();
  bool is_3d = false;
  auto back = garment_from_text(garment_to_text(g, true), "garment.plan", &is_3d);
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_TRUE(is_3d);
  ASSERT_EQ(back->vertices_mm.size(), g.vertices_mm.size());
  for (size_t i = 0; i < g.vertices_mm.size(); ++i) {
    EXPECT_TRUE(same_bits(back->vertices_mm[i].x, g.vertices_mm[i].x)) << i;
    EXPECT_TRUE(same_bits(back->vertices_mm[i].y, g.vertices_mm[i].y)) << i;
    EXPECT_TRUE(same_bits(back->vertices_mm[i].z, g.vertices_mm[i].z)) << i;
  }
  ASSERT_EQ(back->pieces.size(), 1u);
  const auto& p = back->pieces[0];
  for (size_t i = 0; i < p.mesh.vertices_mm.size(); ++i) {
    EXPECT_TRUE(same_bits(p.mesh.vertices_mm[i].x, g.pieces[0].mesh.vertices_mm[i].x));
    EXPECT_TRUE(same_bits(p.mesh.vertices_mm[i].y, g.pieces[0].mesh.vertices_mm[i].y));
  }
  EXPECT_EQ(p.mesh.triangles, g.pieces[0].mesh.triangles);
  EXPECT_EQ(p.mesh.edge_vertices, g.pieces[0].mesh.edge_vertices);
  EXPECT_EQ(p.vertex_3d, g.pieces[0].vertex_3d);
  // The text itself is stable: written again, the same bytes.
  EXPECT_EQ(garment_to_text(*back, true), garment_to_text(g, true));
}

TEST(PlanCodec, ABadGarmentFileIsRefusedNamingTheLine) {
  std::string text = garment_to_text(awkward_garment(), false);
  bool is_3d = true;
  auto bad_index = text;
  bad_index.replace(bad_index.rfind("0 1 2"), 5, "0 1 9");
  auto r = garment_from_text(bad_index, "plan/garment.plan", &is_3d);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("plan/garment.plan: line "), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("3D vertex index below 3"), std::string::npos) << r.error().message;
  EXPECT_FALSE(garment_from_text("", "g", &is_3d));
  EXPECT_FALSE(garment_from_text(text.substr(0, text.size() / 2), "g", &is_3d));
  EXPECT_FALSE(garment_from_text(text + "junk\n", "g", &is_3d));
}

TEST(PlanCodec, MarkersRoundTripAndBadOnesAreRefused) {
  geometry::Marker m;
  m.width_mm = 1400;
  m.length_mm = 852.42712345678901;
  m.utilisation = 0.8123456789;
  m.roll_start_mm = 0;
  m.placements = {{0, 179.99999999999997, false, {10.1, 20.2}}, {1, 0, true, {1.0 / 3.0, 500}}};
  geometry::NestStats stats;
  stats.iterations = {150};
  const std::string text = markers_to_json({m}, stats);
  auto back = markers_from_json(text, "marker.json");
  ASSERT_TRUE(back) << back.error().message;
  ASSERT_EQ(back->size(), 1u);
  EXPECT_TRUE(same_bits((*back)[0].length_mm, m.length_mm));
  ASSERT_EQ((*back)[0].placements.size(), 2u);
  EXPECT_TRUE(same_bits((*back)[0].placements[0].rotation_deg, m.placements[0].rotation_deg));
  EXPECT_TRUE(same_bits((*back)[0].placements[1].offset_mm.x, m.placements[1].offset_mm.x));
  EXPECT_TRUE((*back)[0].placements[1].mirrored);
  EXPECT_EQ(markers_to_json(*back, stats), text);

  for (const char* bad : {"", "[]", "{\"format\": 3}", "{\"format\": \"tp-marker-plan/1\", \"markers\": [{}]}",
                          "{\"format\": \"tp-marker-plan/1\", \"markers\": [{\"width_mm\": 1, \"length_mm\": 1, "
                          "\"utilisation\": 1, \"roll_start_mm\": 0, \"placements\": [{\"piece\": \"a\"}]}]}"}) {
    auto r = markers_from_json(bad, "plan/marker.json");
    ASSERT_FALSE(r) << bad;
    EXPECT_EQ(r.error().message.rfind("plan/marker.json: ", 0), 0u) << r.error().message;
  }
}

TEST(PlanCodec, ASwathDigestSeesEveryByteAndHeaderField) {
  device::Swath s;
  s.header.index = 4;
  s.header.rows = 8;
  s.data = {1, 2, 3, 4};
  const PlannedSwath a = plan_swath(s);
  device::Swath t = s;
  t.data[2] = 9;
  EXPECT_NE(plan_swath(t).digest, a.digest);
  t = s;
  t.header.feed_before_um = 1;
  EXPECT_NE(plan_swath(t).digest, a.digest);
  EXPECT_EQ(plan_swath(s).digest, a.digest);
  auto back = swaths_from_json(swaths_to_json({PlannedSwath{0, 0, 8, 0, 0, 4, "x"}, a}), "swaths.json");
  ASSERT_FALSE(back);  // index 1 holds swath 4: not in order
}

TEST(InputHash, LabelsAndLengthsFrameEveryValue) {
  EXPECT_NE(InputHash().add("a", "bc").hex(), InputHash().add("ab", "c").hex());
  EXPECT_EQ(InputHash().add("x", 0.0).hex(), InputHash().add("x", -0.0).hex());
  EXPECT_NE(InputHash().add("x", 0.1).hex(), InputHash().add("x", std::nextafter(0.1, 1.0)).hex());
  EXPECT_EQ(InputHash().add("x", 1.5).hex().size(), 32u);
}

}  // namespace
}  // namespace tp::host::internal
