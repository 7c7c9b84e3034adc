// geometry/nesting/internal/layout.cpp: placing copies, quantifying their collisions and keeping
// the pairwise loss/weight tracker of the guided local search up to date.
#include "geometry/nesting/internal/layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/nesting/internal/overlap.h"

namespace tp::geometry::nesting {
namespace {

// The overlap proxy's smoothing width, as a fraction of the larger diameter of the two shapes.
constexpr double kProxyEpsilonDiameterRatio = 0.01;
// Keeps a container loss positive for a box that only grazes the outside.
constexpr double kContainerLossFloor = 1e-4;

constexpr double kInf = std::numeric_limits<double>::infinity();
// Largest poles of each shape compared before the exact boundary test.
constexpr size_t kQuickPoles = 4;

Box2 shifted(const Box2& b, Vec2 t) { return {b.min + t, b.max + t}; }

}  // namespace

void make_placed(const OrientedShape& o, const ItemShape& s, const Pose& pose, Vec2 t, Placed& out) {
  out.present = true;
  out.pose = pose;
  out.t = t;
  out.pts.resize(o.pts.size());
  for (size_t i = 0; i < o.pts.size(); ++i) out.pts[i] = o.pts[i] + t;
  out.poles.resize(o.poles.size());
  for (size_t i = 0; i < o.poles.size(); ++i) out.poles[i] = {o.poles[i].c + t, o.poles[i].r};
  out.pole_soa.assign(out.poles);
  out.box = shifted(o.box, t);
  out.hull_area = s.hull_area;
  out.diameter = s.diameter;
  out.original_max_x = o.original_max_x + t.x;
  out.original_min_x = o.original_min_x + t.x;
}

Layout::Layout(const NestContext* ctx, double x_hi) : ctx_(ctx), x_hi_(x_hi) {
  const int n = static_cast<int>(ctx->copy_type.size());
  items_.resize(n);
  boxes_.resize(n);
  hazards_.resize(ctx->hazards.size());
  for (size_t h = 0; h < ctx->hazards.size(); ++h) {
    const ItemShape& s = ctx->hazards[h];
    OrientedShape o;
    o.pts = s.outline;
    o.poles = s.poles;
    for (Vec2 p : s.outline) o.box.add(p);
    make_placed(o, s, Pose{}, Vec2{}, hazards_[h]);
  }
  cols_ = n + static_cast<int>(hazards_.size());
  pairs_.assign(static_cast<size_t>(n) * cols_, PairEntry{});
  container_.assign(n, PairEntry{});
}

const OrientedShape& Layout::shape_for(int k, const Pose& pose, QueryScratch& scratch) const {
  const int type = ctx_->copy_type[k];
  if (pose.index >= 0) return ctx_->oriented[type][pose.index];
  scratch.free_pose = orient(ctx_->shapes[type], pose);
  return scratch.free_pose;
}

double Layout::container_loss(const Box2& box, double hull_area) const {
  const Box2 c{{ctx_->x_lo, ctx_->y_lo}, {x_hi_, ctx_->y_hi}};
  if (box_within(box, c)) return 0;
  const double area = box.width() * box.height();
  const double ix = lo(box.max.x, c.max.x) - hi(box.min.x, c.min.x);
  const double iy = lo(box.max.y, c.max.y) - hi(box.min.y, c.min.y);
  double outside;
  if (ix > 0 && iy > 0) {
    outside = area - ix * iy + kContainerLossFloor * area;
  } else {
    // Entirely outside: pull it back towards the container.
    const Vec2 bc = (box.min + box.max) * 0.5, cc = (c.min + c.max) * 0.5;
    outside = area + norm(bc - cc);
  }
  return 2.0 * std::sqrt(outside) * std::sqrt(hull_area);
}

double Layout::pair_loss(const Vec2* pts, int n, const Box2& box, Vec2 inner, const std::vector<Circle>& poles,
                         Vec2 pole_shift, double hull_a, double diam_a, const Placed& other, QueryScratch& s,
                         double limit) const {
  if (!boxes_touch(box, other.box)) return 0;
  // Overlapping poles prove a collision at once (most rejected samples overlap deeply); only
  // otherwise are the boundaries compared.
  bool hit = false;
  const size_t na = poles.size() < kQuickPoles ? poles.size() : kQuickPoles;
  const size_t nb = other.poles.size() < kQuickPoles ? other.poles.size() : kQuickPoles;
  for (size_t i = 0; i < na && !hit; ++i) {
    const Vec2 c = poles[i].c + pole_shift;
    for (size_t j = 0; j < nb; ++j) {
      const Vec2 d = c - other.poles[j].c;
      const double r = poles[i].r + other.poles[j].r;
      if (d.x * d.x + d.y * d.y < r * r) {
        hit = true;
        break;
      }
    }
  }
  if (!hit) {
    const PolyRef a{pts, n, box, inner};
    const PolyRef b{other.pts.data(), static_cast<int>(other.pts.size()), other.box, other.poles[0].c};
    if (!polygons_collide(a, b, s.edges_a, s.edges_b)) return 0;
  }
  const double eps = kProxyEpsilonDiameterRatio * hi(diam_a, other.diameter);
  const double penalty = std::sqrt(std::sqrt(hull_a) * std::sqrt(other.hull_area));
  // loss = sqrt(proxy + eps^2) * penalty > limit  <=>  proxy > (limit / penalty)^2 - eps^2.
  const double proxy_limit = limit >= kUnbounded ? kUnbounded : (limit / penalty) * (limit / penalty) - eps * eps;
  if (proxy_limit < 0) return kInf;
  const double proxy = overlap_proxy(other.pole_soa, poles, pole_shift, eps, proxy_limit);
  if (proxy > proxy_limit) return kInf;
  return std::sqrt(proxy + eps * eps) * penalty;
}

double Layout::weighted_loss(int k, const Candidate& c, double bound, QueryScratch& s) const {
  const OrientedShape& o = *c.shape;
  const ItemShape& shape = ctx_->shapes[ctx_->copy_type[k]];
  const Box2 box = shifted(o.box, c.t);
  double loss = 0;
  const double cl = container_loss(box, shape.hull_area);
  if (cl > 0) {
    loss += cl * container_[k].weight;
    if (loss > bound) return kInf;
  }
  // Translate the outline once, only if some box is touched.
  bool translated = false;
  const int n = static_cast<int>(o.pts.size());
  auto ensure_pts = [&] {
    if (translated) return;
    s.pts.resize(n);
    for (int i = 0; i < n; ++i) s.pts[i] = o.pts[i] + c.t;
    translated = true;
  };
  const Vec2 inner = o.poles[0].c + c.t;
  const PairEntry* row = &pairs_[static_cast<size_t>(k) * cols_];
  for (int j = 0, m = static_cast<int>(boxes_.size()); j < m; ++j) {
    if (!boxes_touch(box, boxes_[j]) || j == k) continue;
    const Placed& p = items_[j];
    ensure_pts();
    const double l = pair_loss(s.pts.data(), n, box, inner, o.poles, c.t, shape.hull_area, shape.diameter, p, s,
                               (bound - loss) / row[j].weight);
    if (l > 0) {
      loss += l * row[j].weight;
      if (loss > bound) return kInf;
    }
  }
  for (size_t h = 0; h < hazards_.size(); ++h) {
    const Placed& p = hazards_[h];
    if (!boxes_touch(box, p.box)) continue;
    ensure_pts();
    const double w = row[items_.size() + h].weight;
    const double l = pair_loss(s.pts.data(), n, box, inner, o.poles, c.t, shape.hull_area, shape.diameter, p, s,
                               (bound - loss) / w);
    if (l > 0) {
      loss += l * w;
      if (loss > bound) return kInf;
    }
  }
  return loss;
}

bool Layout::collides(int k, const Candidate& c, double x_limit, QueryScratch& s) const {
  const OrientedShape& o = *c.shape;
  const Box2 box = shifted(o.box, c.t);
  if (box.min.x < ctx_->x_lo || box.max.x > x_limit || box.min.y < ctx_->y_lo || box.max.y > ctx_->y_hi) return true;
  const int n = static_cast<int>(o.pts.size());
  bool translated = false;
  const Vec2 inner = o.poles[0].c + c.t;
  auto hit = [&](const Placed& p) {
    if (!translated) {
      s.pts.resize(n);
      for (int i = 0; i < n; ++i) s.pts[i] = o.pts[i] + c.t;
      translated = true;
    }
    const PolyRef a{s.pts.data(), n, box, inner};
    const PolyRef b{p.pts.data(), static_cast<int>(p.pts.size()), p.box, p.poles[0].c};
    return polygons_collide(a, b, s.edges_a, s.edges_b);
  };
  for (int j = 0, m = static_cast<int>(boxes_.size()); j < m; ++j) {
    if (!boxes_touch(box, boxes_[j]) || j == k) continue;
    if (hit(items_[j])) return true;
  }
  for (const Placed& p : hazards_)
    if (boxes_touch(box, p.box) && hit(p)) return true;
  return false;
}

void Layout::place(int k, const Pose& pose, Vec2 t, QueryScratch& scratch, bool track) {
  const OrientedShape& o = shape_for(k, pose, scratch);
  make_placed(o, ctx_->shapes[ctx_->copy_type[k]], pose, t, items_[k]);
  sync_box(k);
  if (track) recompute_row(k, scratch);
}

void Layout::remove(int k) {
  items_[k].present = false;
  sync_box(k);
}

void Layout::sync_box(int k) { boxes_[k] = items_[k].present ? items_[k].box : Box2{}; }

void Layout::recompute_row(int k, QueryScratch& s) {
  const Placed& a = items_[k];
  const int n = static_cast<int>(a.pts.size());
  const Vec2 inner = a.poles[0].c;
  for (int j = 0, m = static_cast<int>(items_.size()); j < m; ++j) {
    double l = 0;
    if (j != k && items_[j].present)
      l = pair_loss(a.pts.data(), n, a.box, inner, a.poles, Vec2{}, a.hull_area, a.diameter, items_[j], s);
    pair(k, j).loss = l;
    pair(j, k).loss = l;
  }
  for (size_t h = 0; h < hazards_.size(); ++h)
    pair(k, static_cast<int>(items_.size() + h)).loss =
        pair_loss(a.pts.data(), n, a.box, inner, a.poles, Vec2{}, a.hull_area, a.diameter, hazards_[h], s);
  container_[k].loss = container_loss(a.box, a.hull_area);
}

void Layout::rebuild_tracker(QueryScratch& scratch) {
  for (PairEntry& e : pairs_) e.loss = 0;
  for (int k = 0; k < size(); ++k)
    if (items_[k].present) recompute_row(k, scratch);
}

void Layout::resize(double new_x_hi, double split_x, QueryScratch& scratch) {
  const double delta = new_x_hi - x_hi_;
  for (int k = 0; k < size(); ++k) {
    Placed& p = items_[k];
    if (!p.present || 0.5 * (p.box.min.x + p.box.max.x) <= split_x) continue;
    const Vec2 shift{delta, 0};
    p.t += shift;
    for (Vec2& v : p.pts) v += shift;
    for (Circle& c : p.poles) c.c += shift;
    p.pole_soa.assign(p.poles);
    p.box = shifted(p.box, shift);
    sync_box(k);
    p.original_max_x += delta;
    p.original_min_x += delta;
  }
  x_hi_ = new_x_hi;
  for (PairEntry& e : pairs_) e = PairEntry{};
  for (PairEntry& e : container_) e = PairEntry{};
  rebuild_tracker(scratch);
}

void Layout::restore_keep_weights(const Layout& other) {
  x_hi_ = other.x_hi_;
  items_ = other.items_;
  boxes_ = other.boxes_;
  for (size_t i = 0; i < pairs_.size(); ++i) pairs_[i].loss = other.pairs_[i].loss;
  for (size_t i = 0; i < container_.size(); ++i) container_[i].loss = other.container_[i].loss;
}

double Layout::total_loss() const {
  double s = 0;
  const int n = size();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < cols_; ++j) s += pair(i, j).loss;
    s += container_[i].loss;
  }
  return s;
}

double Layout::total_weighted_loss() const {
  double s = 0;
  const int n = size();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < cols_; ++j) s += pair(i, j).loss * pair(i, j).weight;
    s += container_[i].loss * container_[i].weight;
  }
  return s;
}

double Layout::item_loss(int k) const {
  double s = container_[k].loss;
  const PairEntry* row = &pairs_[static_cast<size_t>(k) * cols_];
  for (int j = 0; j < cols_; ++j) s += row[j].loss;
  return s;
}

void Layout::update_weights(const GlsWeights& w) {
  double max_loss = 0;
  for (const PairEntry& e : pairs_) max_loss = hi(max_loss, e.loss);
  for (const PairEntry& e : container_) max_loss = hi(max_loss, e.loss);
  auto update = [&](PairEntry& e) {
    const double m = e.loss > 0 ? w.min_increase + (w.max_increase - w.min_increase) * (e.loss / max_loss) : w.decay;
    e.weight = hi(1.0, e.weight * m);
  };
  // Item pairs are stored twice (i,j) and (j,i): update the upper triangle and mirror it.
  const int n = size();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < cols_; ++j) {
      update(pair(i, j));
      if (j < n) pair(j, i).weight = pair(i, j).weight;
    }
    update(container_[i]);
  }
}

double Layout::used_x_hi() const {
  double x = ctx_->x_lo;
  for (const Placed& p : items_)
    if (p.present) x = std::fmax(x, p.box.max.x);
  return x;
}

double Layout::used_original_x_hi() const {
  double x = 0;
  for (const Placed& p : items_)
    if (p.present) x = std::fmax(x, p.original_max_x);
  return x;
}

}  // namespace tp::geometry::nesting
