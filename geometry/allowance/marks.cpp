// geometry/allowance/marks.cpp: label and grain arrow placement in the seam allowance.
#include "geometry/allowance/marks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "geometry/allowance/stroke_font.h"
#include "geometry/common/tolerances.h"

namespace tp::geometry {
namespace {

constexpr double kMargin_mm = 1.0;          // between marks and the seam or cut line
constexpr double kRunTurn_rad = 0.07;       // a "straight" stretch turns less than about 4 degrees
constexpr double kMinLabel_mm = 2.0;        // smallest capital height worth printing
constexpr double kMinArrow_mm = 8.0;
constexpr double kMaxArrow_mm = 40.0;
constexpr double kInsideOffset_mm = 1.5;    // fallback: baseline this far inside the seam line

struct Run {
  int edge = 0;
  Vec2 start, dir;   // dir: unit, along the outline (counter-clockwise)
  double length = 0;
  double width = 0;  // allowance width of the edge
};

std::vector<Run> straight_runs(const Piece& piece, const PieceAllowance& a) {
  std::vector<Run> runs;
  for (size_t e = 0; e < piece.edges.size(); ++e) {
    // A dart's legs fold inside the garment together: no room for marks between them.
    bool dart_leg = false;
    for (const Dart& d : piece.darts) dart_leg |= d.leg_a == static_cast<int>(e) || d.leg_b == static_cast<int>(e);
    if (dart_leg) continue;
    const auto& P = piece.edges[e].points_mm;
    size_t i = 0;
    while (i + 1 < P.size()) {
      const Vec2 d0 = normalized(P[i + 1] - P[i]);
      if (norm(P[i + 1] - P[i]) <= 0) {
        ++i;
        continue;
      }
      size_t j = i + 1;
      while (j + 1 < P.size()) {
        const Vec2 d = P[j + 1] - P[j];
        if (norm(d) > 0 && std::abs(std::atan2(cross(d0, d), dot(d0, d))) > kRunTurn_rad) break;
        ++j;
      }
      Run r;
      r.edge = static_cast<int>(e);
      r.start = P[i];
      // The chord of a gently curved run; the label sits on it.
      r.dir = normalized(P[j] - P[i]);
      r.length = norm(P[j] - P[i]);
      r.width = a.width_mm[e];
      if (r.length > 0) runs.push_back(r);
      i = j;
    }
  }
  return runs;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Glyph polylines mapped onto a run: baseline at distance `d_mm` outside the seam line (negative:
// inside), text centred at `along_mm` from the run start, top towards the piece.
std::vector<std::vector<Vec2>> place_text(const std::string& text, double h, const Run& r, double along_mm, double d_mm) {
  const Vec2 n{r.dir.y, -r.dir.x};  // outward
  const Vec2 up = -n;
  const double w = text_width_mm(text, h);
  const Vec2 origin = r.start + r.dir * (along_mm - 0.5 * w) + n * d_mm;
  auto lines = text_strokes(text, h);
  for (auto& l : lines)
    for (Vec2& p : l) p = origin + r.dir * p.x + up * p.y;
  return lines;
}

double distance_to(const Polygon& poly, Vec2 p) {
  double best = 1e300;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], d = poly[(i + 1) % poly.size()] - a;
    const double len2 = dot(d, d);
    const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, norm(p - (a + d * t)));
  }
  return best;
}

// Whether every stroke (points and segment midpoints) lies on the wanted side of the seam line
// (outside for the allowance, inside for the fallback) between min_mm and max_mm from it: a label
// on a gently curved stretch must not touch the seam line nor reach the cut line.
bool fits(const std::vector<std::vector<Vec2>>& lines, const Polygon& seam, bool outside, double min_mm, double max_mm) {
  for (const auto& l : lines)
    for (size_t i = 0; i < l.size(); ++i)
      for (Vec2 p : {l[i], i + 1 < l.size() ? (l[i] + l[i + 1]) * 0.5 : l[i]}) {
        if (point_in_polygon(seam, p) == outside) return false;
        const double d = distance_to(seam, p);
        if (d < min_mm || d > max_mm) return false;
      }
  return true;
}

std::vector<std::vector<Vec2>> arrow(Vec2 c, Vec2 g, double len) {
  const Vec2 a = c - g * (0.5 * len), b = c + g * (0.5 * len);
  const double head = std::min(3.0, len / 4);
  const Vec2 side = perp(g);
  std::vector<std::vector<Vec2>> out;
  out.push_back({a, b});
  out.push_back({b - g * head + side * (head * 0.5), b, b - g * head - side * (head * 0.5)});
  out.push_back({a + g * head + side * (head * 0.5), a, a + g * head - side * (head * 0.5)});
  return out;
}

}  // namespace

PieceMarks piece_marks(const Piece& piece, const PieceAllowance& allowance, const std::string& size, const Finishing& f) {
  PieceMarks out;
  const std::vector<Run> runs = straight_runs(piece, allowance);
  if (runs.empty()) return out;
  // Longer texts first; each shrinks to the smallest height before a shorter text is tried.
  std::vector<std::string> texts;
  std::string full = upper(piece.name);
  if (!size.empty()) full += " " + upper(size);
  if (!f.job_name.empty()) texts.push_back(full + " " + upper(f.job_name));
  texts.push_back(full);
  texts.push_back(upper(piece.name));

  const Polygon seam = outline(piece);
  std::vector<const Run*> by_length;
  for (const Run& r : runs) by_length.push_back(&r);
  std::stable_sort(by_length.begin(), by_length.end(), [](const Run* a, const Run* b) { return a->length > b->length; });
  std::optional<Run> label_run;
  for (const std::string& text : texts) {
    for (double h = f.label_height_mm; h >= kMinLabel_mm - kBoundarySlack && !label_run; h *= 0.8) {
      const double tw = text_width_mm(text, h);
      const double half_stroke = 0.5 * std::max(0.25, h / 10);
      // The longest run that holds the text, checked against the real (curved) seam line.
      for (const Run* r : by_length) {
        if (r->width < h + 2 * kMargin_mm || r->length < tw + 2 * kMargin_mm) continue;
        auto lines = place_text(text, h, *r, 0.5 * r->length, 0.5 * (r->width + h));
        if (!fits(lines, seam, true, kMargin_mm * 0.5 + half_stroke, r->width - kMargin_mm * 0.5 - half_stroke)) continue;
        label_run = *r;
        out.text = text;
        out.stroke_width_mm = std::max(0.25, h / 10);
        out.label = std::move(lines);
        break;
      }
    }
    if (label_run) break;
  }
  if (!label_run) {
    // No allowance holds even the smallest label: just inside the seam line, small.
    const Run* longest = &runs.front();
    for (const Run& r : runs)
      if (r.length > longest->length) longest = &r;
    const std::string text = texts.back();
    double h = f.label_height_mm;
    while (h > kMinLabel_mm && text_width_mm(text, h) > longest->length - 2 * kMargin_mm) h *= 0.8;
    out.text = text;
    out.in_allowance = false;
    out.stroke_width_mm = std::max(0.25, h / 10);
    out.label = place_text(text, h, *longest, 0.5 * longest->length, -kInsideOffset_mm);
    return out;
  }

  // Grain arrow: the run whose allowance holds the longest arrow along the grain.
  if (!piece.grain || norm(piece.grain->to_mm - piece.grain->from_mm) <= 0) return out;
  const Vec2 g = normalized(piece.grain->to_mm - piece.grain->from_mm);
  double best_len = 0;
  Vec2 best_centre;
  for (const Run& r : runs) {
    const Vec2 n{r.dir.y, -r.dir.x};
    const double room = r.width - 2 * kMargin_mm;
    if (room <= 0) continue;
    const double s = std::abs(dot(g, n));
    double len = std::min(kMaxArrow_mm, 0.4 * r.length);
    if (s > 1e-6) len = std::min(len, room / s);
    Vec2 centre = r.start + r.dir * (0.5 * r.length) + n * (0.5 * r.width);
    const bool shared = r.edge == label_run->edge && norm(r.start - label_run->start) < kSamePoint_mm;
    if (shared) {
      // Beside the label, in the free part of the run before it.
      const double free = 0.5 * (r.length - text_width_mm(out.text, f.label_height_mm)) - 2 * kMargin_mm;
      len = std::min(len, free * std::max(std::abs(dot(g, r.dir)), 1e-3));
      centre = r.start + r.dir * (0.5 * free + kMargin_mm) + n * (0.5 * r.width);
    }
    if (len > best_len && fits(arrow(centre, g, len), seam, true, 0.5 * kMargin_mm, r.width - 0.5 * kMargin_mm)) {
      best_len = len;
      best_centre = centre;
    }
  }
  if (best_len >= kMinArrow_mm) out.grain_arrow = arrow(best_centre, g, best_len);
  return out;
}

}  // namespace tp::geometry
