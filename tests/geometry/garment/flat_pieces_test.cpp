// tests/geometry/garment/flat_pieces_test.cpp: unjoined pieces split off, the rest renumbered, and put back laid flat.
#include "geometry/garment/flat_pieces.h"

#include <gtest/gtest.h>

#include "geometry/garment/flat_garment.h"
#include "geometry/mesh/mesh_pattern.h"
#include "tests/geometry/garment/tube_fixture.h"

namespace tp::geometry {
namespace {

using test_fixture::rectangle;
using test_fixture::tube_pattern;

// The tube with a label first (so the tube's pieces and stitches are renumbered) and a dart-like
// stitch of the label to itself, which does not join it to anything.
Pattern tube_with_label() {
  Pattern p = tube_pattern();
  p.pieces.insert(p.pieces.begin(), rectangle("label", 60, 40));
  for (Stitch& st : p.stitches) ++st.a.piece, ++st.b.piece;
  p.stitches.push_back(Stitch{EdgeSpan{0, 1, 0, -1}, EdgeSpan{0, 3, 0, -1}, false});
  return p;
}

TEST(FlatPieces, APieceSewnOnlyToItselfIsUnjoinedAndAFlatJobHasNone) {
  Pattern p = tube_with_label();
  EXPECT_EQ(unjoined_pieces(p), std::vector<int>{0});
  p.stitches.clear();
  EXPECT_TRUE(unjoined_pieces(p).empty());
}

TEST(FlatPieces, ThePartRenumbersPiecesAndStitchesAndPuttingBackLaysTheLabelFlat) {
  const Pattern p = tube_with_label();
  TriangulateOptions opt;
  opt.target_edge_mm = 30;
  auto meshes = mesh_pattern(p, opt);
  ASSERT_TRUE(meshes) << meshes.error().message;
  const PatternPart part = pattern_without(p, *meshes, {0});
  ASSERT_EQ(part.pattern.pieces.size(), 2u);
  EXPECT_EQ(part.pattern.pieces[0].name, "front");
  EXPECT_EQ(part.pieces, (std::vector<int>{1, 2}));
  ASSERT_EQ(part.pattern.stitches.size(), 2u);
  EXPECT_EQ(part.stitches, (std::vector<int>{0, 1}));
  EXPECT_EQ(part.pattern.stitches[0].a.piece, 0);
  EXPECT_EQ(part.pattern.stitches[0].b.piece, 1);
  EXPECT_EQ(part.meshes.stitch_vertices.size(), 2u);

  // A stand-in for the sewn part: the part laid flat and lifted 500 mm.
  auto part_garment = flat_garment(part.pattern, part.meshes);
  ASSERT_TRUE(part_garment);
  for (Vec3& v : part_garment->vertices_mm) v.z += 500;
  auto whole = garment_with_flat_pieces(p, *meshes, part, *part_garment);
  ASSERT_TRUE(whole) << whole.error().message;
  ASSERT_EQ(whole->pieces.size(), 3u);
  auto laid = flat_garment(p, *meshes);
  ASSERT_TRUE(laid);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(whole->pieces[i].piece, static_cast<int>(i));
  // The label where a flat job lays it, the tube's pieces where the part's garment has them.
  const GarmentPiece& label = whole->pieces[0];
  ASSERT_EQ(label.vertex_3d.size(), laid->pieces[0].vertex_3d.size());
  for (size_t k = 0; k < label.vertex_3d.size(); ++k) {
    const Vec3 a = whole->vertices_mm[label.vertex_3d[k]], b = laid->vertices_mm[laid->pieces[0].vertex_3d[k]];
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.z, 0);
  }
  for (int v : whole->pieces[1].vertex_3d) EXPECT_EQ(whole->vertices_mm[v].z, 500);

  // Without the label: its chart empty, its vertices gone, the others unchanged.
  const Garment worn = garment_without(*whole, {0});
  ASSERT_EQ(worn.pieces.size(), 3u);
  EXPECT_TRUE(worn.pieces[0].vertex_3d.empty());
  EXPECT_TRUE(worn.pieces[0].mesh.triangles.empty());
  EXPECT_EQ(worn.vertices_mm.size(), part_garment->vertices_mm.size());
  for (int v : worn.pieces[2].vertex_3d) EXPECT_EQ(worn.vertices_mm[v].z, 500);
  // Put back from the whole garment: the label's flat chart again.
  const Garment back = with_pieces_from(worn, *whole, {0});
  ASSERT_EQ(back.pieces[0].vertex_3d.size(), label.vertex_3d.size());
  EXPECT_EQ(back.vertices_mm[back.pieces[0].vertex_3d[0]].x, whole->vertices_mm[label.vertex_3d[0]].x);
}

}  // namespace
}  // namespace tp::geometry
