// tests/geometry/nesting/nest_pieces_test.cpp: marker planning for pattern pieces: grain rules,
// mirrored pairs, gaps and margins, defects and the split into markers, checked exactly.
#include "geometry/nesting/nest_pieces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "tests/geometry/nesting/layout_checker.h"

namespace tp::geometry {
namespace {

test::Pts pts(const Polygon& p) {
  test::Pts out;
  for (Vec2 v : p) out.push_back({v.x, v.y});
  return out;
}

// Garment-like pieces (mm): a front with a curved neckline, a sleeve, a cuff.
std::vector<NestItem> garment() {
  std::vector<NestItem> items;
  NestItem front;
  front.piece = 0;
  front.name = "front";
  front.outline_mm = {{0, 0}, {260, 0}, {270, 420}, {200, 520}, {150, 480}, {110, 480}, {60, 520}, {-10, 420}};
  front.quantity = 1;
  items.push_back(front);
  NestItem sleeve;
  sleeve.piece = 1;
  sleeve.name = "sleeve";
  sleeve.outline_mm = {{0, 0}, {300, 0}, {280, 180}, {150, 240}, {20, 180}};
  sleeve.grain = {1, 0};  // drawn with the warp along the piece's x
  sleeve.mirror = PieceMirror::kPairs;
  sleeve.quantity = 1;
  items.push_back(sleeve);
  NestItem cuff;
  cuff.piece = 2;
  cuff.name = "cuff";
  cuff.outline_mm = {{0, 0}, {200, 0}, {200, 60}, {0, 60}};
  cuff.quantity = 4;
  cuff.rotation = PieceRotation::kQuarterTurns;
  items.push_back(cuff);
  return items;
}

NestOptions options() {
  NestOptions o;
  o.fabric_width_mm = 700;
  o.gap_mm = 4;
  o.selvedge_margin_mm = 10;
  o.end_margin_mm = 15;
  o.work_limit = 60;
  o.time_limit_s = 60;
  o.seed = 3;
  return o;
}

Vec2 roll_direction(const PiecePlacement& p, Vec2 v) {
  const Affine2 m = p.piece_to_roll();
  return normalized(m.apply_linear(v));
}

// Pieces of one marker, transformed independently of the engine, in the marker's frame.
std::vector<test::Pts> marker_pieces(const std::vector<NestItem>& items, const Marker& m) {
  std::vector<test::Pts> out;
  for (const PiecePlacement& p : m.placements) {
    const NestItem* it = nullptr;
    for (const NestItem& c : items)
      if (c.piece == p.piece) it = &c;
    // The face-up flip (piece y up, roll y down) comes before the placement's own transform.
    test::Pts face_up = pts(it->outline_mm);
    for (auto& q : face_up) q.second = -q.second;
    out.push_back(test::transform_piece(face_up, p.rotation_deg, p.mirrored, p.offset_mm.x, p.offset_mm.y));
  }
  return out;
}

void expect_legal(const std::vector<NestItem>& items, const NestOptions& o, const Marker& m,
                  const std::vector<test::Pts>& defects = {}) {
  // The marker length adds the end margin to the used length: allow its rounding.
  const double slack = 1e-9 * m.length_mm;
  const auto r = test::check_layout(marker_pieces(items, m), o.selvedge_margin_mm, o.end_margin_mm,
                                    o.fabric_width_mm - o.selvedge_margin_mm, m.length_mm - o.end_margin_mm + slack,
                                    o.gap_mm, defects);
  EXPECT_TRUE(r.ok()) << r.first;
  EXPECT_GT(m.utilisation, 0.3);
  EXPECT_LE(m.utilisation, 1.0);
}

TEST(NestPieces, GrainRotationsLayTheGrainAlongTheRoll) {
  // Piece y up becomes roll -y (the face-up flip): a grain drawn up needs a half turn.
  EXPECT_EQ(grain_rotations_deg({0, 1}, PieceRotation::kGrainBothWays, false), (std::vector<double>{180, 0}));
  EXPECT_EQ(grain_rotations_deg({0, -1}, PieceRotation::kOneWay, false), (std::vector<double>{0}));
  EXPECT_EQ(grain_rotations_deg({1, 0}, PieceRotation::kOneWay, false), (std::vector<double>{90}));
  EXPECT_EQ(grain_rotations_deg({1, 0}, PieceRotation::kOneWay, true), (std::vector<double>{270}));
  EXPECT_EQ(grain_rotations_deg({0, 1}, PieceRotation::kQuarterTurns, false), (std::vector<double>{180, 270, 0, 90}));
  for (bool mirror : {false, true}) {
    for (double deg : grain_rotations_deg({3, 4}, PieceRotation::kOneWay, mirror)) {
      PiecePlacement p;
      p.rotation_deg = deg;
      p.mirrored = mirror;
      const Vec2 d = roll_direction(p, {3, 4});
      EXPECT_NEAR(d.x, 0, 1e-12);
      EXPECT_NEAR(d.y, 1, 1e-12);
    }
  }
}

TEST(NestPieces, OneMarkerHonoursGrainPairsGapAndMargins) {
  const auto items = garment();
  const NestOptions o = options();
  auto markers = nest_pieces(items, o);
  ASSERT_TRUE(markers) << markers.error().what();
  ASSERT_EQ(markers->size(), 1u);
  const Marker& m = markers->front();
  EXPECT_EQ(m.width_mm, 700);
  EXPECT_EQ(m.roll_start_mm, 0);
  ASSERT_EQ(m.placements.size(), 7u);  // front, sleeve pair, four cuffs
  std::map<int, int> count, mirrored;
  for (const PiecePlacement& p : m.placements) {
    ++count[p.piece];
    mirrored[p.piece] += p.mirrored;
    const NestItem& it = items[p.piece];
    const Vec2 g = roll_direction(p, it.grain);
    if (it.rotation == PieceRotation::kQuarterTurns) {
      EXPECT_NEAR(std::fabs(g.x) + std::fabs(g.y), 1, 1e-9) << "grain along or across the roll";
    } else {
      EXPECT_NEAR(std::fabs(g.y), 1, 1e-9) << it.name << ": grain along the roll";
    }
  }
  EXPECT_EQ(count[1], 2);
  EXPECT_EQ(mirrored[1], 1) << "a left/right pair: one of the two mirrored";
  EXPECT_EQ(mirrored[0], 0);
  EXPECT_EQ(count[2], 4);
  expect_legal(items, o, m);
}

TEST(NestPieces, OneWayPiecesKeepTheirDirection) {
  auto items = garment();
  for (NestItem& it : items) it.rotation = PieceRotation::kOneWay;
  auto markers = nest_pieces(items, options());
  ASSERT_TRUE(markers) << markers.error().what();
  for (const PiecePlacement& p : markers->front().placements) {
    const Vec2 g = roll_direction(p, items[p.piece].grain);
    EXPECT_NEAR(g.y, 1, 1e-9) << items[p.piece].name;
  }
}

TEST(NestPieces, MaximumLengthSplitsIntoMarkersAroundDefects) {
  auto items = garment();
  items[2].quantity = 12;
  NestOptions o = options();
  o.max_length_mm = 700;
  o.defects_mm = {{{300, 200}, {360, 200}, {360, 260}, {300, 260}}, {{100, 900}, {200, 900}, {150, 980}}};
  auto markers = nest_pieces(items, o);
  ASSERT_TRUE(markers) << markers.error().what();
  ASSERT_GE(markers->size(), 2u);
  size_t placed = 0;
  double roll = 0;
  for (const Marker& m : *markers) {
    EXPECT_LE(m.length_mm, o.max_length_mm + 1e-9);
    EXPECT_DOUBLE_EQ(m.roll_start_mm, roll);
    roll += m.length_mm;
    placed += m.placements.size();
    std::vector<test::Pts> defects;
    for (const Polygon& d : o.defects_mm) {
      test::Pts local;
      for (Vec2 v : d) local.push_back({v.x, v.y - m.roll_start_mm});
      defects.push_back(local);
    }
    expect_legal(items, o, m, defects);
  }
  EXPECT_EQ(placed, 1u + 2u + 12u);
}

TEST(NestPieces, ErrorsNameThePiece) {
  auto items = garment();
  items[1].grain = {0, 0};
  auto r = nest_pieces(items, options());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidPattern);
  EXPECT_NE(r.error().message.find("sleeve"), std::string::npos) << r.error().message;

  items = garment();
  items[0].outline_mm = {{0, 0}, {900, 0}, {900, 50}, {0, 50}};  // grain along y: 900 mm across
  r = nest_pieces(items, options());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kNesting);
  EXPECT_NE(r.error().message.find("front"), std::string::npos) << r.error().message;

  items = garment();
  items[2].outline_mm = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  r = nest_pieces(items, options());
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("cuff"), std::string::npos) << r.error().message;

  NestOptions o = options();
  o.fabric_width_mm = 0;
  r = nest_pieces(garment(), o);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidArgument);
}

}  // namespace
}  // namespace tp::geometry
