// geometry/body/marching_tetrahedra.cpp: zero-set extraction by marching tetrahedra.
#include "geometry/body/marching_tetrahedra.h"

#include <array>
#include <unordered_map>

namespace tp::geometry {
namespace {

// Cube corners: bit 0 = +x, bit 1 = +y, bit 2 = +z. Six tetrahedra around the 0-7 diagonal.
constexpr std::array<std::array<int, 4>, 6> kTets{{
    {0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}}};

}  // namespace

BodyMesh marching_tetrahedra(const ScalarGrid& g) {
  BodyMesh mesh;
  if (g.nx < 2 || g.ny < 2 || g.nz < 2) return mesh;
  const auto node = [&](int i, int j, int k) { return (static_cast<int64_t>(k) * g.ny + j) * g.nx + i; };
  const auto pos = [&](int64_t id) {
    int i = static_cast<int>(id % g.nx), j = static_cast<int>((id / g.nx) % g.ny), k = static_cast<int>(id / (int64_t(g.nx) * g.ny));
    return g.origin_mm + Vec3{double(i), double(j), double(k)} * g.spacing_mm;
  };
  const auto value = [&](int64_t id) {
    float v = g.values[static_cast<size_t>(id)];
    return v == 0.0f ? 1e-7f : v;  // no vertex exactly on a node: keeps the surface manifold
  };
  // One mesh vertex per crossed grid edge, keyed by its two node ids.
  std::unordered_map<uint64_t, int> edge_vertex;
  const auto crossing = [&](int64_t a, int64_t b) {
    if (a > b) std::swap(a, b);
    const uint64_t key = (static_cast<uint64_t>(a) << 32) | static_cast<uint64_t>(b);  // ids < 2^32
    auto [it, fresh] = edge_vertex.emplace(key, static_cast<int>(mesh.vertices_mm.size()));
    if (fresh) {
      double fa = value(a), fb = value(b);
      mesh.vertices_mm.push_back(pos(a) + (pos(b) - pos(a)) * (fa / (fa - fb)));
    }
    return it->second;
  };
  const auto emit = [&](int a, int b, int c, Vec3 outward) {
    Vec3 n = cross(mesh.vertices_mm[b] - mesh.vertices_mm[a], mesh.vertices_mm[c] - mesh.vertices_mm[a]);
    if (dot(n, outward) < 0) std::swap(b, c);
    if (a != b && b != c && a != c) mesh.triangles.push_back({a, b, c});
  };

  for (int k = 0; k + 1 < g.nz; ++k)
    for (int j = 0; j + 1 < g.ny; ++j)
      for (int i = 0; i + 1 < g.nx; ++i) {
        std::array<int64_t, 8> c;
        int negative = 0;
        for (int b = 0; b < 8; ++b) {
          c[b] = node(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
          negative += value(c[b]) < 0;
        }
        if (negative == 0 || negative == 8) continue;
        for (const auto& t : kTets) {
          std::array<int64_t, 4> in{}, out{};
          int ni = 0, no = 0;
          for (int v : t) (value(c[v]) < 0 ? in[ni++] : out[no++]) = c[v];
          if (ni == 0 || no == 0) continue;
          // Outward direction: from the inside corners' centroid to the outside corners'.
          Vec3 ci{}, co{};
          for (int q = 0; q < ni; ++q) ci += pos(in[q]) / ni;
          for (int q = 0; q < no; ++q) co += pos(out[q]) / no;
          Vec3 outward = co - ci;
          if (ni == 1) {
            emit(crossing(in[0], out[0]), crossing(in[0], out[1]), crossing(in[0], out[2]), outward);
          } else if (ni == 3) {
            emit(crossing(out[0], in[0]), crossing(out[0], in[1]), crossing(out[0], in[2]), outward);
          } else {
            int a = crossing(in[0], out[0]), b = crossing(in[0], out[1]);
            int d = crossing(in[1], out[0]), e = crossing(in[1], out[1]);
            emit(a, b, e, outward);
            emit(a, e, d, outward);
          }
        }
      }
  return mesh;
}

}  // namespace tp::geometry
