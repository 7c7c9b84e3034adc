// geometry/garment/push_out_of_body.cpp: a smooth per-piece push that clears placed pieces of the body.
#include "geometry/garment/push_out_of_body.h"
#include "geometry/common/tolerances.h"

#include <algorithm>
#include <cmath>

namespace tp::geometry {
namespace {

// Passes of the field before giving up on a vertex still too near (each clears what it can).
constexpr int kMaxPasses = 12;
// The field's radius never shrinks below this (mm): a few triangles at any mesh the project sews.
constexpr double kMinRadius_mm = 15;
// A deep vertex's push aims this much beyond the band plus clearance (mm): the next pass, then
// near the surface, finds its exact distance.
constexpr double kDeepExtra_mm = 4;
// Pushes agree in direction when their sum is this fraction of their lengths' sum (and one push
// counts along the mean direction when its cosine with it is above this).
constexpr double kCoherent = 0.7;
// A deep vertex looks for the surface this far (mm), in steps of this.
constexpr double kMaxExit_mm = 300;
constexpr double kExitStep_mm = 4;
// The first passes may move a piece whole; the rest spread a field.
constexpr int kWholePasses = 2;

// The shortest way out of the body from `p` (deeper than the SDF's exact band, where it has no
// normal): rays in 26 directions (the cube's faces, edges and corners), stepped until outside;
// the unit direction of the shortest and its length (mm). The body's horizontal outward
// direction from `axis`, at the band's depth, if no ray leaves within kMaxExit_mm.
Vec3 way_out(const BodySdf& body, Vec3 p, Vec3 axis, double& length_mm) {
  double best = kMaxExit_mm;
  Vec3 best_dir{p.x - axis.x, 0, p.z - axis.z};
  best_dir = norm(best_dir) > kMinDivisor ? normalized(best_dir) : Vec3{0, 0, 1};
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        if (i == 0 && j == 0 && k == 0) continue;
        const Vec3 d = normalized(Vec3{double(i), double(j), double(k)});
        for (double t = kExitStep_mm; t < best; t += kExitStep_mm)
          if (body.approx_distance_mm(p + d * t) > 0) {
            best = t, best_dir = d;
            break;
          }
      }
  length_mm = best < kMaxExit_mm ? best : body.band_mm();
  return best_dir;
}

// The push vertex `p` wants: to `clearance_mm` outside, along the outward normal.
Vec3 wanted_push(const BodySdf& body, Vec3 p, double clearance_mm, Vec3 axis) {
  const BodySdf::Hit h = body.query(p);
  if (h.distance_mm >= clearance_mm) return {0, 0, 0};
  if (h.near && norm(h.normal) > 0.5) return h.normal * (clearance_mm - h.distance_mm);
  // Deeper than the exact band: along the shortest way out.
  double out_mm = 0;
  const Vec3 dir = way_out(body, p, axis, out_mm);
  return dir * (out_mm + clearance_mm + kDeepExtra_mm);
}

// Weight of a push at flat distance r (mm) for a field of radius R: 1 at 0, smooth to 0 at R.
double weight(double r2, double R2) {
  if (r2 >= R2) return 0;
  const double t = 1 - r2 / R2;
  return t * t;
}

// Moves the whole piece when its pushes agree in direction (a panel cutting into the torso):
// by the longest push seen along their mean direction. Returns whether it moved.
bool translate_piece(std::vector<Vec3>& x, const std::vector<Vec3>& push) {
  Vec3 sum{0, 0, 0};
  double len_sum = 0;
  for (const Vec3& p : push) sum = sum + p, len_sum += norm(p);
  if (len_sum == 0 || norm(sum) < kCoherent * len_sum) return false;
  const Vec3 dir = normalized(sum);
  double move = 0;
  for (const Vec3& p : push) {
    const double len = norm(p), c = dot(p, dir) / len;
    if (c > kCoherent) move = std::max(move, len / c);
  }
  for (Vec3& q : x) q = q + dir * move;
  return move > 0;
}

// One pass over one piece: pushes wanted, then the piece moved as a whole if they agree, else
// spread as a field and applied. Returns vertices pushed.
int push_piece(std::vector<Vec3>& x, const std::vector<Vec2>& flat, const BodySdf& body, double clearance_mm,
               double radius_mm, Vec3 axis, bool whole) {
  std::vector<int> pushed;
  std::vector<Vec3> push;
  for (size_t i = 0; i < x.size(); ++i) {
    const Vec3 p = wanted_push(body, x[i], clearance_mm, axis);
    if (norm(p) == 0) continue;
    pushed.push_back(static_cast<int>(i));
    push.push_back(p);
  }
  if (pushed.empty()) return 0;
  if (whole && translate_piece(x, push)) return static_cast<int>(pushed.size());
  const double R2 = radius_mm * radius_mm;
  std::vector<Vec3> field(x.size(), Vec3{0, 0, 0});
  for (size_t j = 0; j < x.size(); ++j) {
    // The weighted mean push, stretched to the largest weighted push's length where the pushes
    // agree in direction (and shrunk where they cancel, e.g. either side of an arm).
    Vec3 sum{0, 0, 0};
    double w_sum = 0, len_sum = 0, len_max = 0;
    for (size_t k = 0; k < pushed.size(); ++k) {
      const Vec2 d = flat[j] - flat[static_cast<size_t>(pushed[k])];
      const double w = weight(d.x * d.x + d.y * d.y, R2);
      if (w == 0) continue;
      const double len = norm(push[k]);
      sum = sum + push[k] * w;
      w_sum += w;
      len_sum += w * len;
      len_max = std::max(len_max, w * len);
    }
    if (w_sum == 0 || len_sum == 0) continue;
    field[j] = (sum / w_sum) * (len_max / (len_sum / w_sum));
  }
  for (size_t j = 0; j < x.size(); ++j) x[j] = x[j] + field[j];
  return static_cast<int>(pushed.size());
}

// Vertices inside the body and inside or nearer than the clearance.
void count(const std::vector<std::vector<Vec3>>& x, const BodySdf& body, double clearance_mm, int& inside, int& close) {
  inside = close = 0;
  for (const auto& piece : x)
    for (const Vec3& p : piece) {
      const double d = body.query(p).distance_mm;
      inside += d < 0;
      close += d < clearance_mm;
    }
}

}  // namespace

void push_out_of_body(std::vector<std::vector<Vec3>>& start_mm, const PatternMesh& meshes, const BodySdf& body,
                      double clearance_mm, double radius_mm, PushOutStats* stats) {
  PushOutStats st;
  const Box3& bb = body.box();
  const Vec3 axis{(bb.min.x + bb.max.x) / 2, 0, (bb.min.z + bb.max.z) / 2};
  for (const auto& piece : start_mm) st.vertices += static_cast<int>(piece.size());
  count(start_mm, body, clearance_mm, st.inside_before, st.close_before);
  // A vertex counts as clear just inside the clearance: the field aims at it exactly.
  const double aim_mm = clearance_mm * 1.05;
  const std::vector<std::vector<Vec3>> placed = start_mm;
  double field_mm = radius_mm;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    int pushed = 0;
    for (size_t pi = 0; pi < start_mm.size() && pi < meshes.pieces.size(); ++pi)
      if (start_mm[pi].size() == meshes.pieces[pi].vertices_mm.size())
        pushed +=
            push_piece(start_mm[pi], meshes.pieces[pi].vertices_mm, body, aim_mm, field_mm, axis, pass < kWholePasses);
    // Pushes that cancel over a wide field (all round a sleeve too narrow for the arm) do not
    // cancel over a narrower one: each further pass halves the field's radius, to a floor.
    if (pass + 1 >= kWholePasses) field_mm = std::max(kMinRadius_mm, field_mm / 2);
    if (pushed == 0) break;
    st.passes = pass + 1;
  }
  count(start_mm, body, clearance_mm, st.inside_after, st.close_after);
  for (size_t pi = 0; pi < start_mm.size(); ++pi)
    for (size_t i = 0; i < start_mm[pi].size(); ++i)
      st.max_push_mm = std::max(st.max_push_mm, norm(start_mm[pi][i] - placed[pi][i]));
  if (stats) *stats = st;
}

}  // namespace tp::geometry
