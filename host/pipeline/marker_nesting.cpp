// host/pipeline/marker_nesting.cpp: the marker stage's nesting items and options from the job.
#include "host/pipeline/marker_nesting.h"

namespace tp::host {

namespace {

geometry::PieceRotation rotation_rule(const std::string& r) {
  if (r == "90") return geometry::PieceRotation::kQuarterTurns;
  if (r == "free") return geometry::PieceRotation::kFree;
  if (r == "fixed") return geometry::PieceRotation::kOneWay;
  return geometry::PieceRotation::kGrainBothWays;
}

}  // namespace

std::vector<geometry::NestItem> marker_nest_items(const geometry::Pattern& pattern,
                                                  const geometry::PieceRenderer& renderer, const MarkerSpec& marker) {
  std::vector<geometry::NestItem> items;
  for (int i = 0; i < renderer.piece_count(); ++i) {
    const geometry::Piece& piece = pattern.pieces[static_cast<size_t>(i)];
    geometry::NestItem item;
    item.piece = i;
    item.name = piece.name;
    item.outline_mm = renderer.cut_outline_mm(i);
    item.rotation = rotation_rule(marker.rotations);
    item.mirror = marker.mirror ? geometry::PieceMirror::kAllowed : geometry::PieceMirror::kNever;
    if (piece.grain && geometry::norm(piece.grain->to_mm - piece.grain->from_mm) > 0)
      item.grain = piece.grain->to_mm - piece.grain->from_mm;
    items.push_back(std::move(item));
  }
  return items;
}

geometry::NestOptions marker_nest_options(const MarkerSpec& m) {
  geometry::NestOptions opt;
  opt.fabric_width_mm = m.fabric_width_mm;
  opt.gap_mm = m.gap_mm;
  opt.selvedge_margin_mm = m.edge_margin_mm;
  opt.end_margin_mm = m.gap_mm;
  for (const auto& d : m.defects)
    opt.defects_mm.push_back({{d.x_mm, d.y_mm},
                              {d.x_mm + d.width_mm, d.y_mm},
                              {d.x_mm + d.width_mm, d.y_mm + d.length_mm},
                              {d.x_mm, d.y_mm + d.length_mm}});
  opt.max_length_mm = m.max_length_mm.value_or(0);
  // A reproducible budget counts separator iterations and reads no clock.
  opt.time_limit_s = m.iterations > 0 ? 0 : m.time_limit_s;
  opt.work_limit = static_cast<std::uint64_t>(m.iterations);
  opt.seed = static_cast<std::uint64_t>(m.seed);
  return opt;
}

}  // namespace tp::host
