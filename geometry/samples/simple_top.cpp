// geometry/samples/simple_top.cpp: the simple top with bust, shoulder and waist darts (4 pieces).
#include <cmath>
#include <numbers>

#include "geometry/body/dress_form.h"
#include "geometry/samples/internal/bodice.h"
#include "geometry/samples/internal/draft.h"
#include "geometry/samples/internal/drafts.h"

namespace tp::geometry::samples::internal {

Result<Pattern> draft_simple_top(const BodyMeasurements& m) {
  BodiceOptions o;
  BodiceBlock block = bodice_block(m, o);
  auto [front_l, back_r] = simple_top_halves(block);
  const DressFormLandmarks l = dress_form_landmarks(m);
  // The halves wrap a cylinder as wide as the top round the bust.
  const double r = (m.bust_mm + o.bust_ease_mm) / (2 * std::numbers::pi);
  front_l.placement = front_placement(r, l.waist_y);
  back_r.placement = back_placement(r, l.waist_y);

  Pattern p;
  p.name = "simple_top";
  p.pieces = {front_l, mirror_piece(front_l, "front_r"), back_r, mirror_piece(back_r, "back_l")};
  struct Seam { const char* name; std::vector<std::pair<std::string, std::string>> a, b; };
  const std::vector<Seam> seams{
      {"centre front", {{"front_l", "cf"}}, {{"front_r", "cf"}}},
      {"centre back", {{"back_r", "cb"}}, {{"back_l", "cb"}}},
      {"left shoulder", {{"front_l", "shoulder"}}, {{"back_l", "shoulder_2"}, {"back_l", "shoulder"}}},
      {"right shoulder", {{"front_r", "shoulder"}}, {{"back_r", "shoulder"}, {"back_r", "shoulder_2"}}},
      {"left side", {{"front_l", "side"}, {"front_l", "side_2"}}, {{"back_l", "side"}}},
      {"right side", {{"front_r", "side_2"}, {"front_r", "side"}}, {{"back_r", "side"}}},
  };
  for (const Seam& s : seams)
    if (auto st = sew_chains(p, s.a, s.b, s.name); !st) return std::unexpected(st.error().with_context("simple_top"));
  if (auto st = stitch_darts(p); !st) return std::unexpected(st.error());
  return p;
}

}  // namespace tp::geometry::samples::internal
