// geometry/design/internal/closest_point.cpp: CGAL AABB tree over triangles, queried for the nearest point.
#include "geometry/design/internal/closest_point.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>

namespace tp::geometry::internal {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangle = K::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

}  // namespace

struct ClosestPointIndex::Impl {
  std::vector<Triangle> triangles;
  Tree tree;
};

ClosestPointIndex::ClosestPointIndex(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& tris)
    : impl_(std::make_unique<Impl>()) {
  impl_->triangles.reserve(tris.size());
  for (const auto& t : tris) {
    auto p = [&](int i) { const Vec3 q = v[static_cast<size_t>(i)]; return K::Point_3(q.x, q.y, q.z); };
    impl_->triangles.emplace_back(p(t[0]), p(t[1]), p(t[2]));
  }
  if (impl_->triangles.empty()) return;
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
}

ClosestPointIndex::~ClosestPointIndex() = default;

MeshHit ClosestPointIndex::first_hit(Vec3 origin, Vec3 direction) const {
  MeshHit hit;
  if (impl_->triangles.empty() || norm(direction) == 0) return hit;
  const K::Ray_3 ray(K::Point_3(origin.x, origin.y, origin.z), K::Vector_3(direction.x, direction.y, direction.z));
  const auto found = impl_->tree.first_intersection(ray);
  if (!found) return hit;
  const K::Point_3* p = boost::get<K::Point_3>(&found->first);
  if (!p) return hit;  // the ray runs inside a triangle's plane: no single point
  hit = nearest({p->x(), p->y(), p->z()});
  hit.distance_mm = norm(hit.point_mm - origin);
  return hit;
}

MeshHit ClosestPointIndex::nearest(Vec3 p) const {
  MeshHit hit;
  if (impl_->triangles.empty()) return hit;
  const K::Point_3 q(p.x, p.y, p.z);
  const auto [point, it] = impl_->tree.closest_point_and_primitive(q);
  hit.triangle = static_cast<int>(it - impl_->triangles.cbegin());
  hit.point_mm = {point.x(), point.y(), point.z()};
  hit.distance_mm = std::sqrt(CGAL::squared_distance(q, point));
  // Barycentric weights of the closest point in its triangle (least squares in the plane).
  const Triangle& t = *it;
  const Vec3 a{t[0].x(), t[0].y(), t[0].z()}, b{t[1].x(), t[1].y(), t[1].z()}, c{t[2].x(), t[2].y(), t[2].z()};
  const Vec3 e0 = b - a, e1 = c - a, d = hit.point_mm - a;
  const double d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d20 = dot(d, e0), d21 = dot(d, e1);
  const double den = d00 * d11 - d01 * d01;
  if (den > 0) {
    const double wb = (d11 * d20 - d01 * d21) / den, wc = (d00 * d21 - d01 * d20) / den;
    hit.bary = {1 - wb - wc, wb, wc};
  } else {
    hit.bary = {1, 0, 0};
  }
  return hit;
}

}  // namespace tp::geometry::internal
