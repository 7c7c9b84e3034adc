// geometry/garment/flat_pieces.cpp: splitting off the unjoined pieces and putting them back laid flat.
#include "geometry/garment/flat_pieces.h"

#include <algorithm>
#include <string>

#include "geometry/garment/flat_garment.h"

namespace tp::geometry {

std::vector<int> unjoined_pieces(const Pattern& pattern) {
  std::vector<int> out;
  if (pattern.stitches.empty()) return out;
  std::vector<bool> joined(pattern.pieces.size(), false);
  for (const Stitch& st : pattern.stitches)
    if (st.a.piece != st.b.piece)
      for (int p : {st.a.piece, st.b.piece})
        if (p >= 0 && static_cast<size_t>(p) < joined.size()) joined[static_cast<size_t>(p)] = true;
  for (size_t p = 0; p < joined.size(); ++p)
    if (!joined[p]) out.push_back(static_cast<int>(p));
  return out;
}

PatternPart pattern_without(const Pattern& pattern, const PatternMesh& meshes, const std::vector<int>& drop) {
  PatternPart part;
  part.pattern = pattern;
  part.pattern.pieces.clear();
  part.pattern.stitches.clear();
  std::vector<int> renumber(pattern.pieces.size(), -1);
  for (size_t p = 0; p < pattern.pieces.size(); ++p) {
    if (std::binary_search(drop.begin(), drop.end(), static_cast<int>(p))) continue;
    renumber[p] = static_cast<int>(part.pieces.size());
    part.pieces.push_back(static_cast<int>(p));
    part.pattern.pieces.push_back(pattern.pieces[p]);
    if (p < meshes.pieces.size()) part.meshes.pieces.push_back(meshes.pieces[p]);
  }
  for (size_t s = 0; s < pattern.stitches.size(); ++s) {
    Stitch st = pattern.stitches[s];
    const auto in = [&](int p) { return p >= 0 && static_cast<size_t>(p) < renumber.size() && renumber[p] >= 0; };
    if (!in(st.a.piece) || !in(st.b.piece)) continue;
    st.a.piece = renumber[static_cast<size_t>(st.a.piece)];
    st.b.piece = renumber[static_cast<size_t>(st.b.piece)];
    part.pattern.stitches.push_back(st);
    part.stitches.push_back(static_cast<int>(s));
    if (s < meshes.stitch_vertices.size()) part.meshes.stitch_vertices.push_back(meshes.stitch_vertices[s]);
  }
  return part;
}

Result<Garment> garment_with_flat_pieces(const Pattern& pattern, const PatternMesh& meshes, const PatternPart& part,
                                         const Garment& part_garment) {
  if (part_garment.pieces.size() != part.pieces.size())
    return fail(ErrorCode::kInvalidArgument, "flat pieces: a garment of " + std::to_string(part_garment.pieces.size()) +
                                                 " pieces for a part of " + std::to_string(part.pieces.size()));
  Garment g;
  g.vertices_mm = part_garment.vertices_mm;
  g.pieces.resize(pattern.pieces.size());
  std::vector<bool> from_part(pattern.pieces.size(), false);
  for (size_t k = 0; k < part.pieces.size(); ++k) {
    const size_t p = static_cast<size_t>(part.pieces[k]);
    g.pieces[p] = part_garment.pieces[k];
    g.pieces[p].piece = static_cast<int>(p);
    from_part[p] = true;
  }
  std::vector<int> flat;
  for (size_t p = 0; p < pattern.pieces.size(); ++p)
    if (!from_part[p]) flat.push_back(static_cast<int>(p));
  if (flat.empty()) return g;
  auto laid = flat_garment(pattern, meshes);
  if (!laid) return fail(laid.error());
  return with_pieces_from(g, *laid, flat);
}

Garment with_pieces_from(const Garment& garment, const Garment& source, const std::vector<int>& pieces) {
  Garment g = garment;
  for (int p : pieces) {
    if (p < 0 || static_cast<size_t>(p) >= g.pieces.size() || static_cast<size_t>(p) >= source.pieces.size()) continue;
    GarmentPiece gp = source.pieces[static_cast<size_t>(p)];
    for (int& v : gp.vertex_3d) {
      g.vertices_mm.push_back(source.vertices_mm[static_cast<size_t>(v)]);
      v = static_cast<int>(g.vertices_mm.size() - 1);
    }
    g.pieces[static_cast<size_t>(p)] = std::move(gp);
  }
  return g;
}

Garment garment_without(const Garment& garment, const std::vector<int>& drop) {
  Garment g;
  g.pieces = garment.pieces;
  std::vector<int> renumber(garment.vertices_mm.size(), -1);
  for (size_t p = 0; p < g.pieces.size(); ++p) {
    GarmentPiece& gp = g.pieces[p];
    if (std::binary_search(drop.begin(), drop.end(), static_cast<int>(p))) {
      gp.mesh = PieceMesh{};
      gp.mesh.edge_vertices.resize(garment.pieces[p].mesh.edge_vertices.size());
      gp.vertex_3d.clear();
      continue;
    }
    for (int& v : gp.vertex_3d) {
      int& r = renumber[static_cast<size_t>(v)];
      if (r < 0) {
        r = static_cast<int>(g.vertices_mm.size());
        g.vertices_mm.push_back(garment.vertices_mm[static_cast<size_t>(v)]);
      }
      v = r;
    }
  }
  return g;
}

}  // namespace tp::geometry
