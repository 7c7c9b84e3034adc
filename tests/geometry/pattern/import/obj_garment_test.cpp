// tests/geometry/pattern/obj_garment_test.cpp: OBJ garments generated here (a 4-panel tube, a 1-panel tube) and broken ones.
#include "geometry/pattern/import/obj_garment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "geometry/pattern/validate.h"

namespace tp::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A tube of `panels` panels around the y axis (radius in cm, OBJ units cm), each panel's texture
/// coordinates laid flat in mm side by side, `cols` x `rows` quads per panel. Seam columns share
/// their 3D vertices; the last panel closes onto the first.
std::string tube_obj(int panels, int cols, int rows, double radius_cm, double height_cm, bool with_groups = true) {
  std::ostringstream s;
  s.precision(17);
  const int ring = panels * cols;  // 3D columns round the tube
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c < ring; ++c) {
      double a = 2 * kPi * c / ring;
      s << "v " << radius_cm * std::sin(a) << " " << height_cm * r / rows << " " << radius_cm * std::cos(a) << "\n";
    }
  const double width_mm = 2 * kPi * radius_cm * 10 / panels;
  const double height_mm = height_cm * 10;
  for (int p = 0; p < panels; ++p)
    for (int r = 0; r <= rows; ++r)
      for (int c = 0; c <= cols; ++c)
        s << "vt " << p * (width_mm + 50) + width_mm * c / cols << " " << height_mm * r / rows << "\n";
  auto v = [&](int p, int c, int r) { return r * ring + (p * cols + c) % ring + 1; };
  auto t = [&](int p, int c, int r) { return p * (rows + 1) * (cols + 1) + r * (cols + 1) + c + 1; };
  for (int p = 0; p < panels; ++p) {
    if (with_groups) s << "g panel" << p << "\n";
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        s << "f";
        for (auto [cc, rr] : {std::pair{c, r}, {c + 1, r}, {c + 1, r + 1}, {c, r + 1}})
          s << " " << v(p, cc, rr) << "/" << t(p, cc, rr) << "/1";
        s << "\n";
      }
  }
  return s.str();
}

TEST(ObjGarment, FourPanelTubeGivesPiecesStitchesAndOneVertexPerSeamPoint) {
  PatternImportOptions o;
  o.obj_position_unit_mm = 10;  // the OBJ is in cm
  const int cols = 6, rows = 8;
  auto r = read_obj_garment(tube_obj(4, cols, rows, 20, 60), "tube.obj", o);
  ASSERT_TRUE(r.has_value()) << r.error().what();
  const Pattern& p = r->pattern;
  ASSERT_EQ(p.pieces.size(), 4u);
  EXPECT_EQ(p.pieces[0].name, "panel0");
  const double width_mm = 2 * kPi * 200 / 4;
  for (const Piece& piece : p.pieces) {
    // Corners split each panel into hem, side, top, side.
    ASSERT_EQ(piece.edges.size(), 4u) << piece.name;
    Box2 box = bounds(outline(piece));
    EXPECT_NEAR(box.width(), width_mm, 1e-6);
    EXPECT_NEAR(box.height(), 600, 1e-6);
    EXPECT_GT(signed_area(outline(piece)), 0);
  }
  // Four vertical seams, each 600 mm on both sides, the sides meeting start to end.
  ASSERT_EQ(p.stitches.size(), 4u);
  for (const Stitch& s : p.stitches) {
    EXPECT_NE(s.a.piece, s.b.piece);
    EXPECT_NEAR(span_length_mm(p, s.a), 600, 1e-6);
    EXPECT_FALSE(s.same_direction);
  }
  Status valid = validate_pattern(p);
  EXPECT_TRUE(valid.has_value()) << valid.error().what();
  // The garment: one 3D vertex per tube vertex; each panel's chart maps its seam columns onto
  // the vertices its neighbours use.
  const Garment& g = r->garment;
  EXPECT_EQ(g.vertices_mm.size(), static_cast<size_t>(4 * cols * (rows + 1)));
  EXPECT_NEAR(norm(Vec3{g.vertices_mm[0].x, 0, g.vertices_mm[0].z}), 200, 1e-9);
  ASSERT_EQ(g.pieces.size(), 4u);
  for (const GarmentPiece& gp : g.pieces) {
    EXPECT_EQ(gp.mesh.vertices_mm.size(), static_cast<size_t>((cols + 1) * (rows + 1)));
    EXPECT_EQ(gp.mesh.triangles.size(), static_cast<size_t>(2 * cols * rows));
    EXPECT_EQ(gp.vertex_3d.size(), gp.mesh.vertices_mm.size());
    ASSERT_EQ(gp.mesh.edge_vertices.size(), 4u);
    for (const auto& ev : gp.mesh.edge_vertices) EXPECT_GE(ev.size(), 2u);
  }
  for (const Stitch& s : p.stitches) {
    const auto& ea = g.pieces[s.a.piece].mesh.edge_vertices[s.a.edge];
    const auto& eb = g.pieces[s.b.piece].mesh.edge_vertices[s.b.edge];
    ASSERT_EQ(ea.size(), eb.size());
    // a's start meets b's end: the same 3D vertex.
    for (size_t k = 0; k < ea.size(); ++k)
      EXPECT_EQ(g.pieces[s.a.piece].vertex_3d[ea[k]], g.pieces[s.b.piece].vertex_3d[eb[eb.size() - 1 - k]]);
  }
  // Texture coordinates are piece mm, so triangles keep their 3D size: compare one quad's width.
  const GarmentPiece& gp = g.pieces[0];
  const auto& tri = gp.mesh.triangles[0];
  double uv_len = norm(gp.mesh.vertices_mm[tri[1]] - gp.mesh.vertices_mm[tri[0]]);
  double len3 = norm(g.vertices_mm[gp.vertex_3d[tri[1]]] - g.vertices_mm[gp.vertex_3d[tri[0]]]);
  EXPECT_NEAR(uv_len, len3, 0.01 * uv_len);  // chord vs arc of 15 degrees
}

TEST(ObjGarment, OnePanelTubeStitchesToItself) {
  auto r = read_obj_garment(tube_obj(1, 12, 3, 10, 20, false), "sleeve.obj");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  ASSERT_EQ(r->pattern.pieces.size(), 1u);
  EXPECT_EQ(r->pattern.pieces[0].name, "piece1");
  ASSERT_EQ(r->pattern.stitches.size(), 1u);
  const Stitch& s = r->pattern.stitches[0];
  EXPECT_EQ(s.a.piece, 0);
  EXPECT_EQ(s.b.piece, 0);
  EXPECT_NE(s.a.edge, s.b.edge);
}

TEST(ObjGarment, BrokenFilesAreNamed) {
  auto msg = [](const std::string& text) {
    auto r = read_obj_garment(text, "g.obj");
    EXPECT_FALSE(r.has_value()) << text;
    return r ? std::string() : r.error().message;
  };
  std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 10 0\nvt 10 10\nvt 0 10\n";
  EXPECT_NE(msg(quad + "f 1 2 3\n").find("g.obj:9: face corner '1' has no texture coordinate"), std::string::npos);
  EXPECT_NE(msg(quad + "f 1/1 2/2 9/3\n").find("g.obj:9: vertex index 9 out of range"), std::string::npos);
  EXPECT_NE(msg(quad + "vt x 1\n").find("g.obj:9: vt needs 2 numbers"), std::string::npos);
  EXPECT_NE(msg(quad + "f 1/1 2/2\n").find("at least 3 corners"), std::string::npos);
  // Clockwise texture coordinates: the piece would print mirror-imaged.
  EXPECT_NE(msg(quad + "f 1/1 2/4 3/3 4/2\n").find("mirrored"), std::string::npos);
  // One texture vertex with two positions.
  EXPECT_NE(msg(quad + "f 1/1 2/2 3/3\nf 1/1 3/3 4/1\n").find("texture vertex 1 is used with two positions"), std::string::npos);
  // Three faces on one 3D edge.
  std::string fan = quad + "v 0 -1 0\nv 0 0 1\nvt 5 -5\nvt 5 5\nf 1/1 2/2 3/3\nf 2/2 1/1 5/5\nf 1/1 2/2 6/6\n";
  EXPECT_NE(msg(fan).find("joins more than two faces"), std::string::npos);
  // A hole: a square ring of 8 quads around a missing middle.
  std::ostringstream ring;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) ring << "v " << x << " " << y << " 0\nvt " << 10 * x << " " << 10 * y << "\n";
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) {
      if (x == 1 && y == 1) continue;
      int a = y * 4 + x + 1;
      ring << "f " << a << "/" << a << " " << a + 1 << "/" << a + 1 << " " << a + 5 << "/" << a + 5 << " " << a + 4 << "/" << a + 4 << "\n";
    }
  EXPECT_NE(msg(ring.str()).find("has holes"), std::string::npos);
  EXPECT_NE(msg("").find("no faces"), std::string::npos);
}

TEST(ObjGarment, NegativeIndicesAndGroups) {
  auto r = read_obj_garment("o front\nv 0 0 0\nv 100 0 0\nv 0 100 0\nvt 0 0\nvt 100 0\nvt 0 100\nf -3/-3 -2/-2 -1/-1\n", "n.obj");
  ASSERT_TRUE(r.has_value()) << r.error().what();
  EXPECT_EQ(r->pattern.pieces[0].name, "front");
  EXPECT_EQ(r->pattern.pieces[0].role, "front");
  EXPECT_EQ(r->pattern.pieces[0].edges.size(), 3u);
}

}  // namespace
}  // namespace tp::geometry
