// boundaryDelaunay: the kernel's tetrahedralization of the nodes, checked and carved.
#include "mesh/volumes/boundary_delaunay.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace geomesh {

namespace {

using Key = std::array<std::uint32_t, 3>;

Key sortedKey(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  Key k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

// Whether every segment of the complex is an edge of the tetrahedra.
bool holdsSegments(const DelaunayTets& dt, const VolumePlc& plc) {
  if (plc.segments.empty()) return true;
  std::vector<std::uint64_t> edges;
  for (std::uint32_t t = 0; t < dt.slotCount(); ++t) {
    if (!dt.alive(t)) continue;
    const std::uint32_t* v = &dt.vertices[4 * std::size_t{t}];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.push_back(vertexPairKey(v[i], v[j]));
  }
  std::sort(edges.begin(), edges.end());
  for (const auto& [a, b] : plcSegments(plc))
    if (!std::binary_search(edges.begin(), edges.end(), vertexPairKey(a, b))) return false;
  return true;
}

}  // namespace

std::optional<DelaunayTets> boundaryDelaunay(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                             const std::vector<Vec3>& holes) {
  if (xyz.size() < 4 || plc.triangles.empty()) return std::nullopt;
  // The complex's triangles, sorted, with whether each is embedded (a duplicate is left to the
  // general recovery).
  std::vector<std::pair<Key, bool>> pieces;
  for (std::size_t t = 0; t < plc.triangles.size(); ++t) {
    const PlcTriangle& c = plc.triangles[t];
    pieces.push_back({sortedKey(std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])),
                      plc.isEmbedded(t)});
  }
  std::sort(pieces.begin(), pieces.end());
  for (std::size_t i = 1; i < pieces.size(); ++i)
    if (pieces[i].first == pieces[i - 1].first) return std::nullopt;

  DelaunayTets dt = DelaunayTets::build(xyz);
  // The piece each half-face is, or -1.
  std::vector<std::int32_t> piece(4 * dt.slotCount(), -1);
  std::vector<int> found(pieces.size(), 0);
  for (std::uint32_t t = 0; t < dt.slotCount(); ++t) {
    if (!dt.alive(t)) continue;
    const std::uint32_t* v = &dt.vertices[4 * std::size_t{t}];
    for (int f = 0; f < 4; ++f) {
      const int* face = DelaunayTets::kFace[f];
      const Key key = sortedKey(v[face[0]], v[face[1]], v[face[2]]);
      const auto it =
          std::lower_bound(pieces.begin(), pieces.end(), std::pair<Key, bool>{key, false});
      if (it == pieces.end() || it->first != key) continue;
      const auto index = static_cast<std::int32_t>(it - pieces.begin());
      piece[4 * std::size_t{t} + f] = index;
      ++found[index];
    }
  }
  if (std::count(found.begin(), found.end(), 0) > 0 || !holdsSegments(dt, plc))
    return std::nullopt;

  // Outside: flooded from the hull faces that are not triangles of the complex, and from the
  // hole points, never across a triangle of the complex.
  std::vector<char> outside(dt.slotCount(), 0);
  std::vector<std::uint32_t> stack;
  auto mark = [&](std::uint32_t t) {
    if (outside[t]) return;
    outside[t] = 1;
    stack.push_back(t);
  };
  for (std::uint32_t t = 0; t < dt.slotCount(); ++t)
    if (dt.alive(t))
      for (int f = 0; f < 4; ++f)
        if (dt.neighbours[4 * std::size_t{t} + f] == kNoTet && piece[4 * std::size_t{t} + f] < 0)
          mark(t);
  for (const Vec3& h : holes) {
    const std::uint32_t t = dt.locate(h, dt.lastTet());
    if (t == kNoTet) return std::nullopt;
    mark(t);
  }
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t n = dt.neighbours[4 * std::size_t{t} + f];
      if (n != kNoTet && piece[4 * std::size_t{t} + f] < 0) mark(n >> 2);
    }
  }
  // What is left must be bounded by the shells exactly: one tetrahedron inside each shell
  // triangle, two on each embedded one, and no other face without an inside neighbour.
  std::vector<int> inside(pieces.size(), 0);
  std::vector<std::uint32_t> tets;
  for (std::uint32_t t = 0; t < dt.slotCount(); ++t) {
    if (!dt.alive(t) || outside[t]) continue;
    for (int f = 0; f < 4; ++f) {
      const std::size_t h = 4 * std::size_t{t} + f;
      const std::uint32_t n = dt.neighbours[h];
      if (piece[h] >= 0)
        ++inside[piece[h]];
      else if (n == kNoTet || outside[n >> 2])
        return std::nullopt;
    }
    const std::uint32_t* v = &dt.vertices[4 * std::size_t{t}];
    tets.insert(tets.end(), v, v + 4);
  }
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (inside[i] != (pieces[i].second ? 2 : 1)) return std::nullopt;
  return complexTetrahedra(plc, xyz, std::move(tets));
}

DelaunayTets complexTetrahedra(const VolumePlc& plc, std::vector<Vec3> points,
                               std::vector<std::uint32_t> tets) {
  DelaunayTets mesh = DelaunayTets::fromTetrahedra(std::move(points), std::move(tets),
                                                   plcTriangles(plc, plc.shellEnd));
  if (!plc.segments.empty()) mesh.keepEdges(plcSegments(plc));
  return mesh;
}

}  // namespace geomesh
