// Neighbours across edges and boundary cycles of triangle sets.
#include "mesh/discrete/triangulation.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <tuple>

namespace geomesh {

namespace {

struct HalfEdge {
  std::uint32_t from, to, triangle, side;
};

// Every edge of every triangle, sorted by its vertex pair (smaller first), so that the uses
// of one edge are consecutive.
std::vector<HalfEdge> sortedHalfEdges(std::span<const TriangleVertices> triangles) {
  std::vector<HalfEdge> edges;
  edges.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t k = 0; k < 3; ++k)
      edges.push_back({triangles[t][k], triangles[t][(k + 1) % 3], t, k});
  auto key = [](const HalfEdge& e) {
    return std::make_tuple(std::min(e.from, e.to), std::max(e.from, e.to), e.triangle, e.side);
  };
  std::sort(edges.begin(), edges.end(),
            [&](const HalfEdge& a, const HalfEdge& b) { return key(a) < key(b); });
  return edges;
}

bool sameEdge(const HalfEdge& a, const HalfEdge& b) {
  return std::min(a.from, a.to) == std::min(b.from, b.to) &&
         std::max(a.from, a.to) == std::max(b.from, b.to);
}

}  // namespace

TriangleAdjacency triangleAdjacency(std::span<const TriangleVertices> triangles) {
  TriangleAdjacency adjacency;
  adjacency.neighbours.assign(triangles.size(), {kNoTriangle, kNoTriangle, kNoTriangle});
  const std::vector<HalfEdge> edges = sortedHalfEdges(triangles);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && sameEdge(edges[i], edges[j])) ++j;
    if (j - i == 2) {
      adjacency.neighbours[edges[i].triangle][edges[i].side] = edges[i + 1].triangle;
      adjacency.neighbours[edges[i + 1].triangle][edges[i + 1].side] = edges[i].triangle;
    } else if (j - i > 2) {
      adjacency.nonManifoldEdges.emplace_back(std::min(edges[i].from, edges[i].to),
                                              std::max(edges[i].from, edges[i].to));
    }
    i = j;
  }
  return adjacency;
}

std::vector<std::vector<std::uint32_t>> boundaryLoops(
    std::span<const TriangleVertices> triangles) {
  // Boundary half-edges: an edge used once. Two uses in the same direction (a flipped
  // neighbour) count as two boundary edges, which keeps every cycle closed.
  const std::vector<HalfEdge> edges = sortedHalfEdges(triangles);
  std::multimap<std::uint32_t, std::uint32_t> next;  // from -> to
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && sameEdge(edges[i], edges[j])) ++j;
    const bool paired = j - i == 2 && edges[i].from == edges[i + 1].to;
    if (!paired && j - i <= 2)
      for (std::size_t k = i; k < j; ++k) next.emplace(edges[k].from, edges[k].to);
    i = j;
  }
  std::vector<std::vector<std::uint32_t>> loops;
  while (!next.empty()) {
    std::vector<std::uint32_t> loop;
    const std::uint32_t start = next.begin()->first;
    std::uint32_t at = start;
    do {
      const auto it = next.find(at);
      if (it == next.end()) break;  // an open chain (only past a non-manifold edge)
      loop.push_back(at);
      at = it->second;
      next.erase(it);
    } while (at != start);
    loops.push_back(std::move(loop));
  }
  return loops;
}

DisjointSets::DisjointSets(std::size_t count) : parent_(count) {
  std::iota(parent_.begin(), parent_.end(), 0u);
}

std::uint32_t DisjointSets::find(std::uint32_t a) {
  while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
  return a;
}

void DisjointSets::join(std::uint32_t a, std::uint32_t b) {
  a = find(a);
  b = find(b);
  if (a != b) parent_[std::max(a, b)] = std::min(a, b);
}

Vec3 triangleNormal(const Triangulation& t, std::uint32_t triangle) {
  const TriangleVertices& v = t.triangles[triangle];
  const Vec3 a = t.points[v[0]], b = t.points[v[1]], c = t.points[v[2]];
  return normalized(cross(b - a, c - a));
}

double triangleArea(const Triangulation& t, std::uint32_t triangle) {
  const TriangleVertices& v = t.triangles[triangle];
  const Vec3 a = t.points[v[0]], b = t.points[v[1]], c = t.points[v[2]];
  return 0.5 * norm(cross(b - a, c - a));
}

}  // namespace geomesh
