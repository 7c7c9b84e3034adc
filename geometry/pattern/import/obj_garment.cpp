// geometry/pattern/obj_garment.cpp: UV islands of an OBJ garment to pieces, stitches and the 3D correspondence.
#include "geometry/pattern/import/obj_garment.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <set>

#include "geometry/mesh/read_obj.h"
#include "geometry/pattern/internal/read_file.h"
#include "geometry/pattern/internal/try.h"
#include "geometry/pattern/role.h"

namespace tp::geometry {
namespace {

/// Texture-space triangles with |area| below this (mm²) count as neither way round.
constexpr double kDegenerateUvArea_mm2 = 1e-12;

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

std::pair<int, int> key(int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }

/// One UV island and its boundary loop.
struct Island {
  std::vector<int> tris;              ///< triangle indices into the mesh
  std::string name;
  std::map<int, int> local;           ///< vt -> local vertex
  std::vector<int> vt_of, v_of;       ///< local vertex -> vt, -> 3D vertex
  std::vector<int> loop;              ///< boundary loop as local vertices, counter-clockwise
  std::vector<bool> brk;              ///< an edge starts at loop position k
};

/// The other occurrence of a boundary edge in 3D: island and loop position, or island -1.
struct Partner {
  int island = -1;
  int pos = 0;
};

double turn_cos(Vec2 a, Vec2 b, Vec2 c) { return dot(normalized(b - a), normalized(c - b)); }

}  // namespace

Result<ObjGarment> read_obj_garment(std::string_view text, const std::string& source_name, const PatternImportOptions& options) {
  TP_TRY(mesh, read_obj(text, source_name, {.require_texture_coordinates = true}));
  if (mesh.triangles.empty()) return fail(ErrorCode::kInvalidPattern, source_name + ": no faces");
  const int nt = static_cast<int>(mesh.triangles.size());

  // 3D edges may join at most two faces.
  std::map<std::pair<int, int>, int> faces_per_edge;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (++faces_per_edge[key(t.c[k].v, t.c[(k + 1) % 3].v)] > 2)
        return fail(ErrorCode::kInvalidPattern, source_name + ":" + std::to_string(t.line) + ": the edge between vertices " +
                                                    std::to_string(t.c[k].v + 1) + " and " + std::to_string(t.c[(k + 1) % 3].v + 1) +
                                                    " joins more than two faces");

  // Islands: faces connected through shared texture-coordinate edges.
  UnionFind uf(nt);
  std::map<std::pair<int, int>, int> uv_edge_face;
  for (int f = 0; f < nt; ++f)
    for (int k = 0; k < 3; ++k) {
      auto e = key(mesh.triangles[f].c[k].vt, mesh.triangles[f].c[(k + 1) % 3].vt);
      auto [it, fresh] = uv_edge_face.emplace(e, f);
      if (!fresh) uf.unite(f, it->second);
    }
  std::map<int, int> island_of_root;
  std::vector<Island> islands;
  for (int f = 0; f < nt; ++f) {
    int r = uf.find(f);
    auto [it, fresh] = island_of_root.emplace(r, static_cast<int>(islands.size()));
    if (fresh) islands.emplace_back();
    islands[it->second].tris.push_back(f);
  }

  // Per island: names, local vertices, orientation, boundary loop.
  std::set<std::string> used_names;
  for (size_t i = 0; i < islands.size(); ++i) {
    Island& is = islands[i];
    std::map<int, int> votes;
    for (int f : is.tris) ++votes[mesh.triangles[f].group];
    int group = std::max_element(votes.begin(), votes.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
    std::string base = group >= 0 ? mesh.groups[group] : "piece" + std::to_string(i + 1);
    is.name = base;
    for (int k = 2; !used_names.insert(is.name).second; ++k) is.name = base + "_" + std::to_string(k);
    const std::string who = source_name + ": island '" + is.name + "'";

    int flipped = 0, upright = 0;
    std::map<std::pair<int, int>, int> directed;
    for (int f : is.tris) {
      const auto& t = mesh.triangles[f];
      for (const auto& c : t.c) {
        auto [it, fresh] = is.local.emplace(c.vt, static_cast<int>(is.vt_of.size()));
        if (fresh) {
          is.vt_of.push_back(c.vt);
          is.v_of.push_back(c.v);
        } else if (is.v_of[it->second] != c.v) {
          return fail(ErrorCode::kInvalidPattern, who + ": texture vertex " + std::to_string(c.vt + 1) +
                                                      " is used with two positions (" + std::to_string(is.v_of[it->second] + 1) +
                                                      " and " + std::to_string(c.v + 1) + ")");
        }
      }
      double area = cross(mesh.uvs[t.c[1].vt] - mesh.uvs[t.c[0].vt], mesh.uvs[t.c[2].vt] - mesh.uvs[t.c[0].vt]);
      if (area > kDegenerateUvArea_mm2) ++upright;
      else if (area < -kDegenerateUvArea_mm2) ++flipped;
      for (int k = 0; k < 3; ++k) ++directed[{is.local[t.c[k].vt], is.local[t.c[(k + 1) % 3].vt]}];
    }
    if (flipped > 0 && upright == 0)
      return fail(ErrorCode::kInvalidPattern, who + ": texture coordinates are mirrored (all faces clockwise); the piece would print mirror-imaged");
    if (flipped > 0)
      return fail(ErrorCode::kInvalidPattern, who + ": " + std::to_string(flipped) + " of " + std::to_string(is.tris.size()) +
                                                  " faces are folded over in texture space");
    // Boundary: directed edges whose reverse is not in the island.
    std::map<int, int> next;
    for (const auto& [e, count] : directed) {
      if (directed.count({e.second, e.first})) continue;
      if (count > 1 || !next.emplace(e.first, e.second).second)
        return fail(ErrorCode::kInvalidPattern, who + ": non-manifold boundary at texture vertex " + std::to_string(is.vt_of[e.first] + 1));
    }
    if (next.empty()) return fail(ErrorCode::kInvalidPattern, who + ": has no boundary (a closed surface cannot be cut flat)");
    int start = next.begin()->first, cur = start;
    do {
      is.loop.push_back(cur);
      auto it = next.find(cur);
      if (it == next.end() || is.loop.size() > next.size())
        return fail(ErrorCode::kInvalidPattern, who + ": boundary does not close at texture vertex " + std::to_string(is.vt_of[cur] + 1));
      cur = it->second;
    } while (cur != start);
    if (is.loop.size() != next.size())
      return fail(ErrorCode::kInvalidPattern, who + ": has holes (" + std::to_string(next.size() - is.loop.size()) +
                                                  " boundary edges outside the outline); cut it open to one outline");
  }

  // Seams: boundary edges of two islands (or two places of one island) sharing a 3D edge.
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> occurrences;
  for (size_t i = 0; i < islands.size(); ++i) {
    const Island& is = islands[i];
    const int n = static_cast<int>(is.loop.size());
    for (int k = 0; k < n; ++k)
      occurrences[key(is.v_of[is.loop[k]], is.v_of[is.loop[(k + 1) % n]])].push_back({static_cast<int>(i), k});
  }
  std::vector<std::vector<Partner>> partner(islands.size());
  for (size_t i = 0; i < islands.size(); ++i) partner[i].assign(islands[i].loop.size(), Partner{});
  for (const auto& [e, occ] : occurrences) {
    if (occ.size() != 2) continue;
    partner[occ[0].first][occ[0].second] = Partner{occ[1].first, occ[1].second};
    partner[occ[1].first][occ[1].second] = Partner{occ[0].first, occ[0].second};
  }

  // Edge breaks: where the neighbour changes or the outline turns a corner, on both sides of a seam.
  const double cos_limit = std::cos(options.corner_angle_deg * std::numbers::pi / 180);
  for (size_t i = 0; i < islands.size(); ++i) {
    Island& is = islands[i];
    const int n = static_cast<int>(is.loop.size());
    is.brk.assign(n, false);
    for (int k = 0; k < n; ++k) {
      const Partner& a = partner[i][(k + n - 1) % n];
      const Partner& b = partner[i][k];
      bool change = (a.island < 0) != (b.island < 0);
      if (!change && a.island >= 0) {
        int m = static_cast<int>(islands[b.island].loop.size());
        int d = ((a.pos - b.pos) % m + m) % m;
        change = a.island != b.island || (d != 1 && d != m - 1);
      }
      Vec2 p = mesh.uvs[is.vt_of[is.loop[(k + n - 1) % n]]], q = mesh.uvs[is.vt_of[is.loop[k]]],
           r = mesh.uvs[is.vt_of[is.loop[(k + 1) % n]]];
      is.brk[k] = change || turn_cos(p, q, r) < cos_limit;
    }
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t i = 0; i < islands.size(); ++i) {
      const Island& is = islands[i];
      const int n = static_cast<int>(is.loop.size());
      for (int k = 0; k < n; ++k) {
        if (!is.brk[k]) continue;
        int v = is.v_of[is.loop[k]];
        for (int e : {(k + n - 1) % n, k}) {
          const Partner& pt = partner[i][e];
          if (pt.island < 0) continue;
          Island& js = islands[pt.island];
          int m = static_cast<int>(js.loop.size());
          for (int pos : {pt.pos, (pt.pos + 1) % m})
            if (js.v_of[js.loop[pos]] == v && !js.brk[pos]) {
              js.brk[pos] = true;
              changed = true;
            }
        }
      }
    }
  }

  // Pieces and their meshes.
  ObjGarment out;
  out.pattern.name = std::filesystem::path(source_name).stem().string();
  for (const Vec3& p : mesh.positions) out.garment.vertices_mm.push_back(p * options.obj_position_unit_mm);
  std::vector<std::vector<int>> edge_of_pos(islands.size());
  for (size_t i = 0; i < islands.size(); ++i) {
    Island& is = islands[i];
    const int n = static_cast<int>(is.loop.size());
    Piece piece;
    piece.name = is.name;
    piece.role = guess_role(is.name);
    GarmentPiece gp;
    gp.piece = static_cast<int>(i);
    for (int vt : is.vt_of) gp.mesh.vertices_mm.push_back(mesh.uvs[vt]);
    gp.vertex_3d = is.v_of;
    for (int f : is.tris) {
      const auto& t = mesh.triangles[f];
      gp.mesh.triangles.push_back({is.local[t.c[0].vt], is.local[t.c[1].vt], is.local[t.c[2].vt]});
    }
    std::vector<int> starts;
    for (int k = 0; k < n; ++k)
      if (is.brk[k]) starts.push_back(k);
    if (starts.empty()) starts.push_back(0);
    edge_of_pos[i].assign(n, 0);
    for (size_t s = 0; s < starts.size(); ++s) {
      int from = starts[s], to = starts[(s + 1) % starts.size()];
      int len = ((to - from) % n + n) % n;
      if (len == 0) len = n;
      Edge e;
      e.name = "e" + std::to_string(s);
      e.curve = len == 1 ? EdgeCurve::kLine : EdgeCurve::kPolyline;
      std::vector<int> ids;
      for (int k = 0; k <= len; ++k) {
        int local = is.loop[(from + k) % n];
        ids.push_back(local);
        e.points_mm.push_back(mesh.uvs[is.vt_of[local]]);
        if (k < len) edge_of_pos[i][(from + k) % n] = static_cast<int>(s);
      }
      piece.edges.push_back(std::move(e));
      gp.mesh.edge_vertices.push_back(std::move(ids));
    }
    out.pattern.pieces.push_back(std::move(piece));
    out.garment.pieces.push_back(std::move(gp));
  }

  // Stitches: each seamed edge once, paired with the edge holding its partner run.
  std::set<std::pair<std::pair<int, int>, std::pair<int, int>>> seen;
  for (size_t i = 0; i < islands.size(); ++i) {
    const Piece& piece = out.pattern.pieces[i];
    const auto& ev = out.garment.pieces[i].mesh.edge_vertices;
    for (int e = 0; e < static_cast<int>(piece.edges.size()); ++e) {
      int first_pos = static_cast<int>(std::find(edge_of_pos[i].begin(), edge_of_pos[i].end(), e) - edge_of_pos[i].begin());
      const Partner& pt = partner[i][first_pos];
      if (pt.island < 0) continue;
      int e2 = edge_of_pos[pt.island][pt.pos];
      auto a = std::pair{static_cast<int>(i), e}, b = std::pair{pt.island, e2};
      if (!seen.insert({std::min(a, b), std::max(a, b)}).second) continue;
      const auto& ev2 = out.garment.pieces[pt.island].mesh.edge_vertices[e2];
      const Island& js = islands[pt.island];
      // Both runs must be the same 3D path, one way round or the other.
      std::vector<int> run_a, run_b;
      for (int l : ev[e]) run_a.push_back(islands[i].v_of[l]);
      for (int l : ev2) run_b.push_back(js.v_of[l]);
      bool same = run_a == run_b;
      std::vector<int> rev_b(run_b.rbegin(), run_b.rend());
      if (!same && run_a != rev_b)
        return fail(ErrorCode::kInvalidPattern, source_name + ": seam between island '" + islands[i].name + "' edge " +
                                                    std::to_string(e) + " and island '" + js.name + "' edge " + std::to_string(e2) +
                                                    " does not follow one 3D path");
      out.pattern.stitches.push_back(Stitch{EdgeSpan{static_cast<int>(i), e, 0, -1}, EdgeSpan{pt.island, e2, 0, -1}, same});
    }
  }
  return out;
}

Result<ObjGarment> load_obj_garment(const std::filesystem::path& path, const PatternImportOptions& options) {
  TP_TRY(text, internal::read_file(path));
  return read_obj_garment(text, path.string(), options);
}

}  // namespace tp::geometry
