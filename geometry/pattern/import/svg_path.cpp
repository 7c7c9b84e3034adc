// geometry/pattern/svg_path.cpp: SVG path-data and transform parsing, arcs to cubic Beziers.
#include "geometry/pattern/import/svg_path.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace tp::geometry {
namespace {

/// Most cubics one arc may become; arcs needing more at the requested tolerance are coarser.
constexpr int kMaxArcCubics = 1024;

/// Reads SVG numbers, flags and command letters from path data or transform arguments.
class Scanner {
 public:
  explicit Scanner(std::string_view s) : s_(s) {}

  void skip_separators() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r' ||
                              s_[i_] == '\f' || s_[i_] == ','))
      ++i_;
  }
  void skip_spaces() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\f'))
      ++i_;
  }
  bool done() const { return i_ >= s_.size(); }
  char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
  void bump() { ++i_; }
  size_t offset() const { return i_; }

  /// Whether the next non-separator character can start a number.
  bool number_ahead() {
    skip_separators();
    char c = peek();
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
  }

  /// One number in SVG syntax: [sign] (digits [. digits] | . digits) [(e|E) [sign] digits].
  bool number(double& out) {
    skip_separators();
    size_t start = i_;
    if (peek() == '+' || peek() == '-') ++i_;
    size_t digits = 0;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_, ++digits;
    if (peek() == '.') {
      ++i_;
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_, ++digits;
    }
    if (digits == 0) {
      i_ = start;
      return false;
    }
    if (peek() == 'e' || peek() == 'E') {
      size_t mark = i_;
      ++i_;
      if (peek() == '+' || peek() == '-') ++i_;
      size_t exp_digits = 0;
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_, ++exp_digits;
      if (exp_digits == 0) i_ = mark;  // "2em": the number ends before the 'e'
    }
    std::string_view tok = s_.substr(start, i_ - start);
    if (tok.front() == '+') tok.remove_prefix(1);
    auto res = std::from_chars(tok.data(), tok.data() + tok.size(), out);
    if (res.ec == std::errc::result_out_of_range) out = tok.front() == '-' ? -HUGE_VAL : HUGE_VAL;
    else if (res.ec != std::errc()) return false;
    return std::isfinite(out);
  }

  /// An arc flag: a single '0' or '1', which may be written without a separator after it.
  bool flag(bool& out) {
    skip_separators();
    if (peek() != '0' && peek() != '1') return false;
    out = peek() == '1';
    ++i_;
    return true;
  }

 private:
  std::string_view s_;
  size_t i_ = 0;
};

SvgSegment segment(SvgSegment::Kind kind, Vec2 from, Vec2 to) {
  SvgSegment s;
  s.kind = kind;
  s.from = from;
  s.to = to;
  return s;
}

Error parse_error(const Scanner& sc, const std::string& what) {
  return Error{ErrorCode::kParse, "path data: " + what + " at offset " + std::to_string(sc.offset())};
}

}  // namespace

Result<std::vector<SvgSubpath>> parse_svg_path(std::string_view d) {
  Scanner sc(d);
  std::vector<SvgSubpath> out;
  Vec2 cur{}, start{};
  Vec2 last_cubic_c2{}, last_quad_c{};
  char prev_cmd = 0;
  char cmd = 0;
  bool pending_new_subpath = false;
  auto current = [&]() -> SvgSubpath& {
    if (out.empty() || pending_new_subpath) {
      out.push_back(SvgSubpath{start, {}, false});
      pending_new_subpath = false;
    }
    return out.back();
  };
  while (true) {
    sc.skip_separators();
    if (sc.done()) break;
    char c = sc.peek();
    bool explicit_cmd = std::isalpha(static_cast<unsigned char>(c)) != 0;
    if (explicit_cmd) {
      if (std::string_view("MmLlHhVvCcSsQqTtAaZz").find(c) == std::string_view::npos)
        return std::unexpected(parse_error(sc, std::string("unknown command '") + c + "'"));
      cmd = c;
      sc.bump();
    } else if (cmd == 0) {
      return std::unexpected(parse_error(sc, "path data must start with a moveto"));
    } else if (cmd == 'Z' || cmd == 'z') {
      return std::unexpected(parse_error(sc, "number after closepath"));
    }
    if (out.empty() && cmd != 'M' && cmd != 'm') return std::unexpected(parse_error(sc, "path data must start with a moveto"));
    bool rel = std::islower(static_cast<unsigned char>(cmd)) != 0;
    Vec2 base = rel ? cur : Vec2{};
    char up = static_cast<char>(std::toupper(static_cast<unsigned char>(cmd)));
    double v[7];
    auto read = [&](int n) -> bool {
      for (int k = 0; k < n; ++k)
        if (!sc.number(v[k])) return false;
      return true;
    };
    switch (up) {
      case 'M': {
        if (!read(2)) return std::unexpected(parse_error(sc, "moveto needs x y"));
        cur = base + Vec2{v[0], v[1]};
        start = cur;
        out.push_back(SvgSubpath{start, {}, false});
        pending_new_subpath = false;
        // Further coordinate pairs are implicit linetos.
        cmd = rel ? 'l' : 'L';
        break;
      }
      case 'Z': {
        if (!out.empty() && !pending_new_subpath) {
          SvgSubpath& sp = out.back();
          if (norm(cur - start) > 0) sp.segments.push_back(segment(SvgSegment::Kind::kLine, cur, start));
          sp.closed = true;
        }
        cur = start;
        pending_new_subpath = true;
        break;
      }
      case 'L':
      case 'H':
      case 'V': {
        Vec2 to = cur;
        if (up == 'L') {
          if (!read(2)) return std::unexpected(parse_error(sc, "lineto needs x y"));
          to = base + Vec2{v[0], v[1]};
        } else if (up == 'H') {
          if (!read(1)) return std::unexpected(parse_error(sc, "horizontal lineto needs x"));
          to.x = rel ? cur.x + v[0] : v[0];
        } else {
          if (!read(1)) return std::unexpected(parse_error(sc, "vertical lineto needs y"));
          to.y = rel ? cur.y + v[0] : v[0];
        }
        current().segments.push_back(segment(SvgSegment::Kind::kLine, cur, to));
        cur = to;
        break;
      }
      case 'C':
      case 'S': {
        SvgSegment seg = segment(SvgSegment::Kind::kCubic, cur, cur);
        if (up == 'C') {
          if (!read(6)) return std::unexpected(parse_error(sc, "curveto needs 6 numbers"));
          seg.c1 = base + Vec2{v[0], v[1]};
          seg.c2 = base + Vec2{v[2], v[3]};
          seg.to = base + Vec2{v[4], v[5]};
        } else {
          if (!read(4)) return std::unexpected(parse_error(sc, "smooth curveto needs 4 numbers"));
          // The first control reflects the previous cubic's second one (or is the current point).
          bool follows = prev_cmd == 'C' || prev_cmd == 'S';
          seg.c1 = follows ? cur * 2.0 - last_cubic_c2 : cur;
          seg.c2 = base + Vec2{v[0], v[1]};
          seg.to = base + Vec2{v[2], v[3]};
        }
        current().segments.push_back(seg);
        last_cubic_c2 = seg.c2;
        cur = seg.to;
        break;
      }
      case 'Q':
      case 'T': {
        SvgSegment seg = segment(SvgSegment::Kind::kQuadratic, cur, cur);
        if (up == 'Q') {
          if (!read(4)) return std::unexpected(parse_error(sc, "quadratic curveto needs 4 numbers"));
          seg.c1 = base + Vec2{v[0], v[1]};
          seg.to = base + Vec2{v[2], v[3]};
        } else {
          if (!read(2)) return std::unexpected(parse_error(sc, "smooth quadratic curveto needs x y"));
          bool follows = prev_cmd == 'Q' || prev_cmd == 'T';
          seg.c1 = follows ? cur * 2.0 - last_quad_c : cur;
          seg.to = base + Vec2{v[0], v[1]};
        }
        current().segments.push_back(seg);
        last_quad_c = seg.c1;
        cur = seg.to;
        break;
      }
      case 'A': {
        SvgSegment seg = segment(SvgSegment::Kind::kArc, cur, cur);
        if (!read(3)) return std::unexpected(parse_error(sc, "arc needs rx ry rotation"));
        seg.rx = std::abs(v[0]);
        seg.ry = std::abs(v[1]);
        seg.x_rotation_deg = v[2];
        if (!sc.flag(seg.large_arc) || !sc.flag(seg.sweep))
          return std::unexpected(parse_error(sc, "arc flags must be 0 or 1"));
        if (!read(2)) return std::unexpected(parse_error(sc, "arc needs x y"));
        seg.to = base + Vec2{v[0], v[1]};
        current().segments.push_back(seg);
        cur = seg.to;
        break;
      }
      default:
        return std::unexpected(parse_error(sc, "unknown command"));
    }
    prev_cmd = up;
  }
  return out;
}

std::vector<std::array<Vec2, 3>> svg_arc_to_cubics(const SvgSegment& a, double tolerance) {
  std::vector<std::array<Vec2, 3>> out;
  Vec2 p0 = a.from, p1 = a.to;
  auto straight = [&] {
    out.push_back({p0 + (p1 - p0) / 3.0, p0 + (p1 - p0) * (2.0 / 3.0), p1});
    return out;
  };
  if (norm(p1 - p0) <= 0) return out;
  double rx = a.rx, ry = a.ry;
  if (!(rx > 0) || !(ry > 0)) return straight();
  // Endpoint to centre parameterisation (SVG 1.1 implementation notes F.6.5).
  double phi = a.x_rotation_deg * std::numbers::pi / 180, cp = std::cos(phi), sp = std::sin(phi);
  Vec2 h = (p0 - p1) * 0.5;
  Vec2 q{cp * h.x + sp * h.y, -sp * h.x + cp * h.y};
  double lambda = (q.x * q.x) / (rx * rx) + (q.y * q.y) / (ry * ry);
  if (lambda > 1) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  double num = rx * rx * ry * ry - rx * rx * q.y * q.y - ry * ry * q.x * q.x;
  double den = rx * rx * q.y * q.y + ry * ry * q.x * q.x;
  double k = den > 0 ? std::sqrt(std::max(0.0, num / den)) : 0;
  if (a.large_arc == a.sweep) k = -k;
  Vec2 cq{k * rx * q.y / ry, -k * ry * q.x / rx};
  Vec2 mid = (p0 + p1) * 0.5;
  Vec2 centre{cp * cq.x - sp * cq.y + mid.x, sp * cq.x + cp * cq.y + mid.y};
  auto angle = [](Vec2 u, Vec2 v) {
    return std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
  };
  Vec2 u{(q.x - cq.x) / rx, (q.y - cq.y) / ry};
  Vec2 w{(-q.x - cq.x) / rx, (-q.y - cq.y) / ry};
  double theta = angle({1, 0}, u);
  double delta = angle(u, w);
  if (!a.sweep && delta > 0) delta -= 2 * std::numbers::pi;
  if (a.sweep && delta < 0) delta += 2 * std::numbers::pi;
  if (!std::isfinite(theta) || !std::isfinite(delta)) return straight();
  // Quarter turns at most; more pieces until the cubic's radial error (~r (d/2)^6 / 54 for a
  // piece of angle d) is within the tolerance.
  double r = std::max(rx, ry);
  int n = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / (std::numbers::pi / 2))));
  while (n < kMaxArcCubics && r * std::pow(std::abs(delta) / n / 2, 6) / 54 > tolerance) n *= 2;
  n = std::min(n, kMaxArcCubics);
  double step = delta / n;
  double kk = 4.0 / 3.0 * std::tan(step / 4);
  auto map = [&](double x, double y) {
    return Vec2{centre.x + cp * rx * x - sp * ry * y, centre.y + sp * rx * x + cp * ry * y};
  };
  for (int i = 0; i < n; ++i) {
    double t1 = theta + step * i, t2 = t1 + step;
    Vec2 c1 = map(std::cos(t1) - kk * std::sin(t1), std::sin(t1) + kk * std::cos(t1));
    Vec2 c2 = map(std::cos(t2) + kk * std::sin(t2), std::sin(t2) - kk * std::cos(t2));
    Vec2 e = i + 1 == n ? p1 : map(std::cos(t2), std::sin(t2));
    out.push_back({c1, c2, e});
  }
  return out;
}

Result<Affine2> parse_svg_transform(std::string_view text) {
  Affine2 result;
  size_t i = 0;
  while (true) {
    while (i < text.size() && (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ',')) ++i;
    if (i >= text.size()) break;
    size_t name_start = i;
    while (i < text.size() && (std::isalpha(static_cast<unsigned char>(text[i])))) ++i;
    std::string_view name = text.substr(name_start, i - name_start);
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (name.empty() || i >= text.size() || text[i] != '(')
      return fail(ErrorCode::kParse, "transform: expected a function at offset " + std::to_string(name_start));
    size_t close = text.find(')', i);
    if (close == std::string_view::npos) return fail(ErrorCode::kParse, "transform: missing ')'");
    Scanner sc(text.substr(i + 1, close - i - 1));
    std::vector<double> args;
    double v;
    while (sc.number(v)) args.push_back(v);
    sc.skip_separators();
    if (!sc.done()) return fail(ErrorCode::kParse, "transform: bad argument in " + std::string(name));
    i = close + 1;
    Affine2 t;
    auto count_is = [&](std::initializer_list<size_t> ok) {
      return std::find(ok.begin(), ok.end(), args.size()) != ok.end();
    };
    if (name == "translate" && count_is({1, 2})) {
      t = Affine2::translation({args[0], args.size() > 1 ? args[1] : 0});
    } else if (name == "scale" && count_is({1, 2})) {
      t = Affine2::scale(args[0], args.size() > 1 ? args[1] : args[0]);
    } else if (name == "rotate" && count_is({1, 3})) {
      t = Affine2::rotation_deg(args[0]);
      if (args.size() == 3)
        t = Affine2::translation({args[1], args[2]}).compose(t).compose(Affine2::translation({-args[1], -args[2]}));
    } else if (name == "matrix" && count_is({6})) {
      t = Affine2{args[0], args[2], args[4], args[1], args[3], args[5]};
    } else if (name == "skewX" && count_is({1})) {
      t = Affine2{1, std::tan(args[0] * std::numbers::pi / 180), 0, 0, 1, 0};
    } else if (name == "skewY" && count_is({1})) {
      t = Affine2{1, 0, 0, std::tan(args[0] * std::numbers::pi / 180), 1, 0};
    } else {
      return fail(ErrorCode::kParse, "transform: unknown function or wrong argument count: " + std::string(name) + "(" +
                                         std::to_string(args.size()) + " arguments)");
    }
    result = result.compose(t);
  }
  return result;
}

}  // namespace tp::geometry
