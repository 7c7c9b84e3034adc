// geometry/pattern/suggest_stitches.cpp: scoring edge pairs (lengths, corners, notches, names) and picking greedily.
#include "geometry/pattern/suggest_stitches.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <set>

#include "geometry/pattern/internal/free_edge_chains.h"
#include "geometry/pattern/internal/text.h"
#include "geometry/pattern/outline_segments.h"
#include "geometry/pattern/validate.h"

namespace tp::geometry {
namespace {

/// Corners at a seam end adding up to more than this far from a straight line score zero.
constexpr double kCornerSlack_rad = std::numbers::pi / 6;
/// An edge is at the bottom of its piece (a hem) when all of it lies this close (mm, or 3 % of
/// the piece height) to the lowest point along the grain.
constexpr double kHemBand_mm = 10;
constexpr double kHemBandRatio = 0.03;
/// Notches closer than this (mm) along an edge form one group (a double notch is two slits).
constexpr double kNotchGroupGap_mm = 8;
/// Seams whose ends differ in height by less than this (mm) on both sides run across the grain:
/// their heights say nothing about which way round they go.
constexpr double kLevelSeam_mm = 20;
/// A centre seam (a piece sewn to its mirror copy) rises at least this fraction of its chord.
constexpr double kCentreSeamAlongGrain = 0.7;

struct EdgeInfo {
  int piece = 0, edge = 0;
  double len = 0;
  double corner_start = std::numbers::pi, corner_end = std::numbers::pi;  ///< interior angles at the ends
  std::vector<double> notches;                  ///< positions from the start, mm
  double rise = 0;                              ///< height along the grain of the end above the start, mm
  double depth = 0;                             ///< middle of the edge below the piece's top, as a fraction of its height
  double piece_height = 0;                      ///< extent of the piece along the grain, mm
  const Edge* geometry = nullptr;
  Vec2 up{0, 1};
  /// Height along the grain at arc length s above the start, mm.
  double rise_at(double s) const { return dot(point_along_edge(*geometry, s) - geometry->points_mm.front(), up); }
  std::string base_name;                        ///< lower case, without "_mirror" and digits
  bool generic_name = true;                     ///< "e12" and the like say nothing
  bool hem = false;
  bool used = false;
};

double interior_angle(const Edge& in, const Edge& out) {
  Vec2 din = edge_end_direction(in, true), dout = edge_end_direction(out, false);
  double turn = std::atan2(cross(din, dout), dot(din, dout));
  return std::numbers::pi - turn;
}

std::string base_name(std::string n, bool& generic) {
  const std::string suffix = "_mirror";
  if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
    n.resize(n.size() - suffix.size());
  std::string out;
  for (char c : n)
    if (std::isalpha(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  generic = out.size() <= 1;
  return out;
}

std::vector<EdgeInfo> describe(const Pattern& pattern) {
  std::vector<EdgeInfo> out;
  std::set<std::pair<int, int>> stitched;
  for (const Stitch& s : pattern.stitches) {
    stitched.insert({s.a.piece, s.a.edge});
    stitched.insert({s.b.piece, s.b.edge});
  }
  for (int p = 0; p < static_cast<int>(pattern.pieces.size()); ++p) {
    const Piece& piece = pattern.pieces[p];
    const int n = static_cast<int>(piece.edges.size());
    // "Down" along the grain (pointing the way of the piece's y axis when the grain is unsigned).
    Vec2 up{0, 1};
    if (piece.grain && norm(piece.grain->to_mm - piece.grain->from_mm) > 0) {
      up = normalized(piece.grain->to_mm - piece.grain->from_mm);
      if (dot(up, Vec2{0, 1}) < 0) up = -up;
    }
    double lo = 1e300, hi = -1e300;
    for (Vec2 q : outline(piece)) {
      lo = std::min(lo, dot(q, up));
      hi = std::max(hi, dot(q, up));
    }
    const double band = std::max(kHemBand_mm, kHemBandRatio * (hi - lo));
    for (int e = 0; e < n; ++e) {
      EdgeInfo info;
      info.piece = p;
      info.edge = e;
      const Edge& edge = piece.edges[e];
      info.len = edge_length_mm(edge);
      if (n > 1) {
        info.corner_start = interior_angle(piece.edges[(e + n - 1) % n], edge);
        info.corner_end = interior_angle(edge, piece.edges[(e + 1) % n]);
      }
      for (const Notch& nt : piece.notches)
        if (nt.edge == e) info.notches.push_back(nt.position_mm);
      std::sort(info.notches.begin(), info.notches.end());
      info.base_name = base_name(edge.name, info.generic_name);
      info.piece_height = hi - lo;
      if (hi > lo) info.depth = (hi - dot(point_along_edge(edge, info.len / 2), up)) / (hi - lo);
      info.geometry = &edge;
      info.up = up;
      info.rise = edge.points_mm.empty() ? 0 : dot(edge.points_mm.back() - edge.points_mm.front(), up);
      info.hem = std::all_of(edge.points_mm.begin(), edge.points_mm.end(), [&](Vec2 q) { return dot(q, up) - lo <= band; });
      info.used = stitched.count({p, e}) > 0;
      for (const Dart& d : piece.darts) info.used = info.used || d.leg_a == e || d.leg_b == e;
      out.push_back(std::move(info));
    }
  }
  return out;
}

/// How well a seam end continues a free edge: 1 when the two interior angles meeting there make a
/// straight line (drafting squares corners so hems and necklines run on), 0 when 30 deg off. Ends
/// where more pieces meet (underarms) need not, so a seam takes the better of its two ends.
double corner_score(double sum_at_one_end, double sum_at_other_end) {
  double dev = std::min(std::abs(sum_at_one_end - std::numbers::pi), std::abs(sum_at_other_end - std::numbers::pi));
  return std::max(0.0, 1 - dev / kCornerSlack_rad);
}

/// Notch groups (position, count) of sorted positions: slits closer than kNotchGroupGap_mm are
/// one notch (a double notch marks the back, a single one the front).
std::vector<std::pair<double, int>> notch_groups(const std::vector<double>& sorted) {
  std::vector<std::pair<double, int>> out;
  for (size_t i = 0; i < sorted.size();) {
    size_t j = i + 1;
    while (j < sorted.size() && sorted[j] - sorted[j - 1] <= kNotchGroupGap_mm) ++j;
    double sum = 0;
    for (size_t k = i; k < j; ++k) sum += sorted[k];
    out.push_back({sum / static_cast<double>(j - i), static_cast<int>(j - i)});
    i = j;
  }
  return out;
}

/// Notch groups of `a` within [from, from + span] against those of `b` laid onto that span with
/// b's start at its end (right sides together); groups match when they have the same number of
/// slits and lie within `tol`. Returns (matched groups counted on both sides, all groups).
std::pair<int, int> notch_matches(const std::vector<double>& a, double from, double span, const std::vector<double>& b,
                                  double b_len, double tol) {
  std::vector<double> mine;
  for (double s : a)
    if (s >= from - tol && s <= from + span + tol) mine.push_back(s - from);
  auto ga = notch_groups(mine), gb = notch_groups(b);
  std::vector<bool> taken(ga.size(), false);
  int matched = 0;
  for (const auto& [t, count] : gb) {
    double at = (b_len - t) * (b_len > 0 ? span / b_len : 0);
    for (size_t k = 0; k < ga.size(); ++k)
      if (!taken[k] && ga[k].second == count && std::abs(ga[k].first - at) <= tol) {
        taken[k] = true;
        matched += 2;
        break;
      }
  }
  return {matched, static_cast<int>(ga.size() + gb.size())};
}

/// Pieces of about the same height hang side by side (fronts and backs): a seam between them
/// lies at the same depth below both tops. 0.5 when the pieces differ in height (a sleeve against
/// a bodice, a waistband against a skirt), where depth says nothing.
double depth_score(const EdgeInfo& a, const EdgeInfo& b) {
  double ha = a.piece_height, hb = b.piece_height;
  if (!(ha > 0) || !(hb > 0) || std::max(ha, hb) > 1.33 * std::min(ha, hb)) return 0.5;
  return std::max(0.0, 1 - 2 * std::abs(a.depth - b.depth));
}

/// Sewn right sides together, a's start meets b's end: pieces hang with their grain vertical, so
/// the rise of a from start to end equals the rise of b from end to start. 0.5 when both are level.
double rise_score(double rise_a, double rise_b_reversed) {
  if (std::abs(rise_a) < kLevelSeam_mm && std::abs(rise_b_reversed) < kLevelSeam_mm) return 0.5;
  return std::max(0.0, 1 - std::abs(rise_a - rise_b_reversed) / (std::abs(rise_a) + std::abs(rise_b_reversed)));
}

double notch_score(std::pair<int, int> m) { return m.second == 0 ? 0.5 : static_cast<double>(m.first) / m.second; }

struct Candidate {
  double score = 0;
  std::vector<int> edges;  ///< indices into the EdgeInfo list
  std::vector<Stitch> stitches;
  std::string reason;
};

bool mirror_twins(const Pattern& pattern, const EdgeInfo& a, const EdgeInfo& b) {
  if (a.piece != b.piece || !pattern.pieces[a.piece].fold_line_mm) return false;
  const auto& ea = pattern.pieces[a.piece].edges[a.edge].name;
  const auto& eb = pattern.pieces[b.piece].edges[b.edge].name;
  return ea + "_mirror" == eb || eb + "_mirror" == ea;
}

/// Whether edge `from` is followed by edge `to`, directly or with only one dart's legs between.
bool runs_into(const Piece& piece, int from, int to) {
  const int n = static_cast<int>(piece.edges.size());
  if ((from + 1) % n == to) return true;
  int l1 = (from + 1) % n, l2 = (from + 2) % n;
  if ((from + 3) % n != to) return false;
  for (const Dart& d : piece.darts)
    if (d.leg_a == l1 && d.leg_b == l2) return true;
  return false;
}

bool adjacent(const Pattern& pattern, const EdgeInfo& a, const EdgeInfo& b) {
  if (a.piece != b.piece) return false;
  int n = static_cast<int>(pattern.pieces[a.piece].edges.size());
  return (a.edge + 1) % n == b.edge || (b.edge + 1) % n == a.edge;
}

/// Pieces sewn along one long edge to a run of several edges (a waist, a neckline, a sleeve end).
bool band_role(const std::string& role) { return role == "waistband" || role == "collar" || role == "cuff"; }

/// Where a band sewn round a whole loop starts: at a centre seam (between mirror copies) if there
/// is one, else at a seam between two pieces, else at the loop's first edge.
size_t loop_start(const Pattern& pattern, const std::vector<internal::EdgeRef>& loop) {
  size_t best = 0;
  int best_rank = -1;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Piece& before = pattern.pieces[loop[(i + loop.size() - 1) % loop.size()].piece];
    const Piece& after = pattern.pieces[loop[i].piece];
    int rank = &before == &after ? 0 : 1;
    if (rank && !before.source_piece.empty() && before.source_piece == after.source_piece &&
        before.mirrored != after.mirrored)
      rank = 2;
    if (rank > best_rank) best = i, best_rank = rank;
  }
  return best;
}

/// A band's free long edge sewn along a run of at least three free edges the chosen stitches
/// leave (a waistband round a skirt's waist across its darts and side seams), the band's start
/// meeting the run's end. The best run by length within max_ease_ratio, or nothing.
std::optional<StitchSuggestion> band_suggestion(const Pattern& pattern, const std::vector<EdgeInfo>& info,
                                                const std::vector<int>& first_info, const std::vector<bool>& taken,
                                                const std::vector<Stitch>& sewn, const SuggestOptions& o) {
  std::optional<StitchSuggestion> best;
  double best_r = 1e300;
  const auto chains = internal::free_edge_chains(pattern, sewn);
  for (size_t bi = 0; bi < info.size(); ++bi) {
    const EdgeInfo& E = info[bi];
    if (E.used || taken[bi] || !band_role(pattern.pieces[E.piece].role) || !(E.len > 0)) continue;
    for (const auto& chain : chains) {
      const size_t m = chain.edges.size();
      auto at = [&](size_t k) -> const EdgeInfo& {
        const auto& r = chain.edges[k % m];
        return info[static_cast<size_t>(first_info[r.piece] + r.edge)];
      };
      for (size_t i = 0; i < m; ++i)
        for (size_t k = 3; k <= m && (chain.closed || i + k <= m); ++k) {
          const bool full_loop = chain.closed && k == m;
          if (full_loop && i != loop_start(pattern, chain.edges)) continue;
          double total = 0;
          bool ok = true;
          for (size_t t = 0; t < k && ok; ++t) {
            const EdgeInfo& c = at(i + t);
            ok = c.piece != E.piece && !c.hem && !taken[static_cast<size_t>(first_info[c.piece] + c.edge)];
            total += c.len;
          }
          if (!ok || !(total > 0)) continue;
          const double r = std::abs(E.len - total) / total;
          // A whole loop (a waist all round) is the surer match of two equally long runs.
          const double rank = full_loop ? r : r + 0.01;
          if (r > o.max_ease_ratio || rank >= best_r) continue;
          best_r = rank;
          StitchSuggestion sg;
          double from = 0, acc = 0;
          for (size_t t = k; t-- > 0;) {  // the band runs along the chain backwards
            const EdgeInfo& c = at(i + t);
            acc += c.len;
            const double to = t == 0 ? -1 : E.len * acc / total;
            sg.stitches.push_back(Stitch{EdgeSpan{E.piece, E.edge, from, to}, EdgeSpan{c.piece, c.edge, 0, -1}, false});
            from = to;
          }
          sg.score = (full_loop ? 0.9 : 0.8) - 0.1 * r / o.max_ease_ratio;
          sg.reason = "band '" + pattern.pieces[E.piece].name + "' edge '" +
                      pattern.pieces[E.piece].edges[E.edge].name + "' " + internal::mm(E.len) + " mm along " +
                      std::to_string(k) + " edges of " + internal::mm(total) + " mm" +
                      (full_loop ? " (all round)" : "");
          best = std::move(sg);
        }
    }
  }
  return best;
}

}  // namespace

std::vector<StitchSuggestion> suggest_stitches(const Pattern& pattern, const SuggestOptions& o) {
  std::vector<StitchSuggestion> out;
  // Darts first: their legs are sewn to each other, mouth to mouth.
  for (int p = 0; p < static_cast<int>(pattern.pieces.size()); ++p)
    for (const Dart& d : pattern.pieces[p].darts) {
      bool stitched = false;
      for (const Stitch& s : pattern.stitches)
        stitched = stitched || (s.a.piece == p && (s.a.edge == d.leg_a || s.a.edge == d.leg_b));
      if (!stitched)
        out.push_back(StitchSuggestion{{Stitch{EdgeSpan{p, d.leg_a, 0, -1}, EdgeSpan{p, d.leg_b, 0, -1}, false}}, 1.0,
                                       "dart '" + d.name + "' of piece '" + pattern.pieces[p].name + "'"});
    }

  std::vector<EdgeInfo> info = describe(pattern);
  const int n = static_cast<int>(info.size());
  std::vector<Candidate> cands;
  // Whole edge against whole edge.
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const EdgeInfo& a = info[i];
      const EdgeInfo& b = info[j];
      if (a.used || b.used || (a.hem && b.hem) || mirror_twins(pattern, a, b) || adjacent(pattern, a, b)) continue;
      double longer = std::max(a.len, b.len);
      if (!(longer > 0)) continue;
      double r = std::abs(a.len - b.len) / longer;
      if (r > o.length_tolerance_ratio) continue;
      // Cubic: a few millimetres of ease (a back shoulder eased onto the front) barely count, the
      // tolerance's edge counts fully.
      double q = r / o.length_tolerance_ratio;
      double s_len = 1 - q * q * q;
      double s_corner = corner_score(a.corner_start + b.corner_end, a.corner_end + b.corner_start);
      auto nm = notch_matches(a.notches, 0, a.len, b.notches, b.len, o.notch_match_mm);
      double s_notch = notch_score(nm);
      double s_name = (a.generic_name || b.generic_name) ? 0.5 : (a.base_name == b.base_name ? 1.0 : 0.25);
      double s_rise = rise_score(a.rise, -b.rise);
      // A sleeve (or cuff) is a tube of its own: its two side edges close it. Other pieces rarely
      // close on themselves, and a piece's edge rarely meets the same edge of its mirror copy
      // (only a centre seam does), so those pairings yield to any equally good alternative.
      const Piece& pa = pattern.pieces[a.piece];
      const Piece& pb = pattern.pieces[b.piece];
      bool tube_role = pa.role == "sleeve" || pa.role == "cuff";
      double adjust = 0;
      if (a.piece == b.piece) adjust = tube_role ? 0.1 : -0.1;
      bool mirror_copies = a.piece != b.piece && !pa.source_piece.empty() && pa.source_piece == pb.source_piece &&
                           pa.mirrored != pb.mirrored && pa.edges[a.edge].name == pb.edges[b.edge].name;
      if (mirror_copies) {
        // Only a centre seam joins a piece to its mirror copy along the same edge, and a centre
        // seam runs along the grain.
        const auto& pts = pa.edges[a.edge].points_mm;
        double chord = norm(pts.back() - pts.front());
        if (!(std::abs(a.rise) >= kCentreSeamAlongGrain * chord)) continue;
        adjust -= 0.1;
      }
      double s_depth = depth_score(a, b);
      double score = 0.2 * s_len + 0.3 * s_rise + 0.1 * s_corner + 0.25 * s_notch + 0.05 * s_name + 0.1 * s_depth + adjust;
      std::string reason = "lengths " + internal::mm(a.len) + "/" + internal::mm(b.len) + " mm, corners " +
                           internal::mm(s_corner) + ", heights " + internal::mm(s_rise) + ", depths " + internal::mm(s_depth) + ", notch groups " +
                           std::to_string(nm.first) + " of " + std::to_string(nm.second) + " matched";
      cands.push_back(Candidate{score, {i, j},
                                {Stitch{EdgeSpan{a.piece, a.edge, 0, -1}, EdgeSpan{b.piece, b.edge, 0, -1}, false}},
                                reason});
    }
  // One edge against two in turn: E[0, s] to F, E[s, end] to G.
  if (n <= o.max_edges_for_splits)
    for (int e = 0; e < n; ++e) {
      const EdgeInfo& E = info[e];
      if (E.used) continue;
      for (int f = 0; f < n; ++f) {
        const EdgeInfo& F = info[f];
        if (F.used || F.piece == E.piece || F.len >= E.len) continue;
        for (int g = 0; g < n; ++g) {
          const EdgeInfo& G = info[g];
          if (g == f || G.used || G.piece == E.piece) continue;
          // Two edges of one piece only when G runs into F, directly or across a dart (sewn, the
          // dart closes): one seam with a corner or a dart on that side.
          if (G.piece == F.piece && !runs_into(pattern.pieces[F.piece], G.edge, F.edge)) continue;
          double total = F.len + G.len;
          double r = std::abs(E.len - total) / total;
          if (r > o.max_ease_ratio) continue;
          double split = E.len * F.len / total;
          double s_len = 1 - 0.5 * r / o.max_ease_ratio;
          auto m1 = notch_matches(E.notches, 0, split, F.notches, F.len, o.notch_match_mm);
          auto m2 = notch_matches(E.notches, split, E.len - split, G.notches, G.len, o.notch_match_mm);
          double s_notch = notch_score({m1.first + m2.first, m1.second + m2.second});
          // The rise of E's two parts, measured straight from end to end.
          double up_split = E.rise_at(split);
          double s_rise = 0.5 * (rise_score(up_split, -F.rise) + rise_score(E.rise - up_split, -G.rise));
          // All three ends of such a seam are junctions of several pieces, so corners say nothing.
          // Slightly below a whole-edge match of the same quality: two seams are a bolder guess.
          double score = 0.95 * (0.3 * s_len + 0.3 * s_rise + 0.4 * s_notch);
          std::string reason = "length " + internal::mm(E.len) + " mm against " + internal::mm(F.len) + " + " +
                               internal::mm(G.len) + " mm, heights " +
                               internal::mm(s_rise) + ", notch groups " + std::to_string(m1.first + m2.first) + " of " +
                               std::to_string(m1.second + m2.second) + " matched";
          cands.push_back(Candidate{score, {e, f, g},
                                    {Stitch{EdgeSpan{E.piece, E.edge, 0, split}, EdgeSpan{F.piece, F.edge, 0, -1}, false},
                                     Stitch{EdgeSpan{E.piece, E.edge, split, -1}, EdgeSpan{G.piece, G.edge, 0, -1}, false}},
                                    reason});
        }
      }
    }
  std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  std::vector<bool> taken(n, false);
  for (const Candidate& c : cands) {
    if (c.score < o.min_score) break;
    if (std::any_of(c.edges.begin(), c.edges.end(), [&](int k) { return taken[k]; })) continue;
    for (int k : c.edges) taken[k] = true;
    out.push_back(StitchSuggestion{c.stitches, c.score, c.reason});
  }
  // Bands last: the runs they are sewn along exist once the other seams are chosen.
  std::vector<int> first_info(pattern.pieces.size(), 0);
  for (int k = n - 1; k >= 0; --k) first_info[info[k].piece] = k;
  for (;;) {
    std::vector<Stitch> sewn = pattern.stitches;
    for (const StitchSuggestion& sg : out) sewn.insert(sewn.end(), sg.stitches.begin(), sg.stitches.end());
    auto band = band_suggestion(pattern, info, first_info, taken, sewn, o);
    if (!band || band->score < o.min_score) break;
    for (const Stitch& st : band->stitches) {
      taken[first_info[st.a.piece] + st.a.edge] = true;
      taken[first_info[st.b.piece] + st.b.edge] = true;
    }
    out.push_back(std::move(*band));
  }
  // A suggested seam whose sides differ beyond the validator's tolerance is an eased one (a back
  // shoulder eased onto the front): marked with its ratio, as importers mark theirs, so it is
  // valid as suggested and reported with the eased seams.
  for (StitchSuggestion& sg : out) {
    double most = 0;
    for (Stitch& st : sg.stitches)
      if (st.ease_ratio == 0) {
        st.ease_ratio = mismatch_ease_ratio(pattern, st);
        most = std::max(most, st.ease_ratio);
      }
    if (most > 0) {
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.3f", most);
      sg.reason += std::string("; eased (longer side up to ") + ratio + " times the shorter)";
    }
  }
  return out;
}

int accept_suggestions(Pattern& pattern, const std::vector<StitchSuggestion>& suggestions, double min_score) {
  int added = 0;
  for (const StitchSuggestion& s : suggestions) {
    if (s.score < min_score) continue;
    for (const Stitch& st : s.stitches) {
      pattern.stitches.push_back(st);
      ++added;
    }
  }
  return added;
}

}  // namespace tp::geometry
