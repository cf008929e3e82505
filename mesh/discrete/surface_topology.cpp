// Topology report of a triangulation: edges from sorted vertex pairs, components by union-find
// over vertices, boundary loops by walking the edges used once.
#include "mesh/discrete/surface_topology.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace geomesh {
namespace {

constexpr double kDegenerateArea = 1e-12;  // twice the area, relative to the longest edge squared

struct EdgeUse {
  std::uint32_t low, high;
  bool forward;  // the triangle runs it from low to high
};

std::vector<EdgeUse> sortedEdgeUses(std::span<const TriangleVertices> triangles) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (const TriangleVertices& v : triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      if (a != b) uses.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.low != y.low ? x.low < y.low : x.high < y.high;
  });
  return uses;
}

struct Edge {
  std::uint32_t a, b;
};

// Cycles of the boundary edges, walked without orientation (a flipped triangle next to the
// boundary still closes its loop); returns the first vertex of each.
std::vector<std::uint32_t> boundaryLoopStarts(std::span<const Edge> edges,
                                              std::size_t vertexCount) {
  std::vector<std::uint32_t> offset(vertexCount + 1, 0);
  for (const Edge& e : edges) ++offset[e.a + 1], ++offset[e.b + 1];
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<std::uint32_t> incident(offset.back()), filled(offset.begin(), offset.end() - 1);
  for (std::uint32_t i = 0; i < edges.size(); ++i)
    incident[filled[edges[i].a]++] = i, incident[filled[edges[i].b]++] = i;
  std::vector<bool> walked(edges.size(), false);
  std::vector<std::uint32_t> nextAt(offset.begin(), offset.end() - 1), starts;
  auto unwalkedEdgeAt = [&](std::uint32_t v) -> std::int64_t {
    while (nextAt[v] < offset[v + 1] && walked[incident[nextAt[v]]]) ++nextAt[v];
    return nextAt[v] < offset[v + 1] ? std::int64_t{incident[nextAt[v]]} : std::int64_t{-1};
  };
  for (std::uint32_t first = 0; first < edges.size(); ++first) {
    if (walked[first]) continue;
    walked[first] = true;
    const std::uint32_t start = edges[first].a;
    std::uint32_t at = edges[first].b;
    while (at != start) {
      const std::int64_t e = unwalkedEdgeAt(at);
      if (e < 0) break;  // an open chain, past a non-manifold edge
      walked[e] = true;
      at = edges[e].a == at ? edges[e].b : edges[e].a;
    }
    starts.push_back(start);
  }
  return starts;
}

bool isDegenerate(const Triangulation& t, const TriangleVertices& v) {
  if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) return true;
  const Vec3 a = t.points[v[0]], b = t.points[v[1]], c = t.points[v[2]];
  const double longest = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
  return norm(cross(b - a, c - a)) <= kDegenerateArea * longest;
}

// Per component (indexed by its root vertex): V, E, F and boundary loops.
struct ComponentCounts {
  std::int64_t vertices = 0, edges = 0, triangles = 0, loops = 0;
};

}  // namespace

SurfaceTopologyReport surfaceTopology(const Triangulation& t) {
  SurfaceTopologyReport report;
  const std::size_t n = t.points.size();
  DisjointSets sets(n);
  std::vector<bool> used(n, false);
  for (const TriangleVertices& v : t.triangles) {
    for (std::uint32_t k : v) used[k] = true;
    sets.join(v[0], v[1]), sets.join(v[1], v[2]);
    if (isDegenerate(t, v)) ++report.degenerateTriangles;
  }
  std::vector<ComponentCounts> counts(n);
  for (std::uint32_t v = 0; v < n; ++v)
    if (used[v]) ++report.vertices, ++counts[sets.find(v)].vertices;
  for (const TriangleVertices& v : t.triangles) ++counts[sets.find(v[0])].triangles;

  const std::vector<EdgeUse> uses = sortedEdgeUses(t.triangles);
  std::vector<Edge> boundary;
  for (std::size_t i = 0, j; i < uses.size(); i = j) {
    for (j = i + 1; j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high;)
      ++j;
    ++report.edges, ++counts[sets.find(uses[i].low)].edges;
    if (j - i == 1) boundary.push_back({uses[i].low, uses[i].high});
    if (j - i == 2 && uses[i].forward == uses[i + 1].forward) ++report.inconsistentEdges;
    if (j - i > 2) ++report.nonManifoldEdges;
  }
  for (std::uint32_t start : boundaryLoopStarts(boundary, n))
    ++report.boundaryLoops, ++counts[sets.find(start)].loops;

  report.triangles = t.triangles.size();
  report.euler = static_cast<int>(static_cast<std::int64_t>(report.vertices) -
                                  static_cast<std::int64_t>(report.edges) +
                                  static_cast<std::int64_t>(report.triangles));
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!used[v] || sets.find(v) != v) continue;
    const ComponentCounts& c = counts[v];
    ++report.components;
    report.genus += static_cast<int>((2 - (c.vertices - c.edges + c.triangles) - c.loops) / 2);
  }
  return report;
}

std::vector<bool> boundaryVertices(const Triangulation& t) {
  std::vector<bool> onBoundary(t.points.size(), false);
  const TriangleAdjacency adjacency = triangleAdjacency(t.triangles);
  for (std::size_t tri = 0; tri < t.triangles.size(); ++tri)
    for (int k = 0; k < 3; ++k)
      if (adjacency.neighbours[tri][k] == kNoTriangle)
        onBoundary[t.triangles[tri][k]] = onBoundary[t.triangles[tri][(k + 1) % 3]] = true;
  return onBoundary;
}

}  // namespace geomesh
