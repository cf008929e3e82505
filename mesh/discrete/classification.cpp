// Patches by dihedral angle, the curves and points between them, and the repairs of merged
// triangulations, all on sort-based edge tables (O(n log n)).
#include "mesh/discrete/classification.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

namespace geomesh {

namespace {

// The distinct edges of a triangle list and the triangle sides that use each of them.
struct EdgeTable {
  std::vector<std::array<std::uint32_t, 2>> ends;  // smaller vertex first; sorted
  std::vector<std::uint32_t> firstUse;             // edge e: uses[firstUse[e], firstUse[e + 1])
  std::vector<std::uint32_t> uses;                 // triangle * 3 + side

  std::size_t size() const { return ends.size(); }
  std::span<const std::uint32_t> usesOf(std::size_t e) const {
    return std::span(uses).subspan(firstUse[e], firstUse[e + 1] - firstUse[e]);
  }
};

EdgeTable edgeTable(std::span<const TriangleVertices> triangles) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      keyed.emplace_back(std::uint64_t{std::min(a, b)} << 32 | std::max(a, b), 3 * t + k);
    }
  std::sort(keyed.begin(), keyed.end());
  EdgeTable table;
  table.uses.reserve(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    if (i == 0 || keyed[i].first != keyed[i - 1].first) {
      const std::uint64_t key = keyed[i].first;
      table.ends.push_back(
          {static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>(key)});
      table.firstUse.push_back(static_cast<std::uint32_t>(i));
    }
    table.uses.push_back(keyed[i].second);
  }
  table.firstUse.push_back(static_cast<std::uint32_t>(keyed.size()));
  return table;
}

// The vertex a triangle side starts from.
std::uint32_t useFrom(std::span<const TriangleVertices> triangles, std::uint32_t use) {
  return triangles[use / 3][use % 3];
}

// Joins the two triangles of each manifold edge for which `joined(a, b)` holds.
template <class Joined>
void joinAcrossManifoldEdges(const EdgeTable& edges, DisjointSets& sets, Joined joined) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto uses = edges.usesOf(e);
    if (uses.size() != 2 || edges.ends[e][0] == edges.ends[e][1]) continue;
    const std::uint32_t a = uses[0] / 3, b = uses[1] / 3;
    if (a != b && joined(a, b)) sets.join(a, b);
  }
}

// Consecutive labels of the sets, numbered in the order of their smallest element.
std::vector<int> componentLabels(DisjointSets& sets, std::size_t count) {
  std::vector<int> labels(count, -1);
  int next = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t root = sets.find(i);  // root <= i: labelled already, or i itself
    if (labels[root] < 0) labels[root] = next++;
    labels[i] = labels[root];
  }
  return labels;
}

void checkLabels(const Triangulation& t, std::span<const int> labels) {
  if (!labels.empty() && labels.size() != t.triangles.size())
    throw std::invalid_argument("triangle labels: one per triangle expected");
}

int labelOf(std::span<const int> labels, std::uint32_t triangle) {
  return labels.empty() ? 0 : labels[triangle];
}

std::vector<TriangleVertices> gather(const Triangulation& t,
                                     std::span<const std::uint32_t> triangles) {
  std::vector<TriangleVertices> subset;
  subset.reserve(triangles.size());
  for (std::uint32_t i : triangles) subset.push_back(t.triangles[i]);
  return subset;
}

// Triangles of each label, ascending; labels are 0-based and consecutive.
std::vector<std::vector<std::uint32_t>> groupByLabel(std::span<const int> labels) {
  std::vector<std::vector<std::uint32_t>> groups;
  for (std::uint32_t i = 0; i < labels.size(); ++i) {
    const auto label = static_cast<std::size_t>(labels[i]);
    if (label >= groups.size()) groups.resize(label + 1);
    groups[label].push_back(i);
  }
  return groups;
}

std::vector<int> splitIntoDisks(const Triangulation& t, std::span<const int> labels) {
  std::vector<std::vector<std::uint32_t>> pending = groupByLabel(labels), disks;
  while (!pending.empty()) {
    std::vector<std::uint32_t> region = std::move(pending.back());
    pending.pop_back();
    if (region.empty()) continue;
    // Halves are never empty, so this ends at single triangles at worst.
    if (region.size() == 1 || patchShape(t, region).isDisk()) {
      disks.push_back(std::move(region));
      continue;
    }
    for (auto& half : splitPatch(t, region)) pending.push_back(std::move(half));
  }
  std::sort(disks.begin(), disks.end(),
            [](const auto& a, const auto& b) { return a.front() < b.front(); });
  std::vector<int> result(labels.size());
  for (std::size_t d = 0; d < disks.size(); ++d)
    for (std::uint32_t i : disks[d]) result[i] = static_cast<int>(d);
  return result;
}

// Per triangle side (triangle * 3 + k), the side of the other triangle on its edge when exactly
// two triangles use it, else kNoTriangle.
std::vector<std::uint32_t> sidesAcross(std::span<const TriangleVertices> triangles) {
  std::vector<std::uint32_t> across(3 * triangles.size(), kNoTriangle);
  const EdgeTable edges = edgeTable(triangles);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto uses = edges.usesOf(e);
    if (uses.size() != 2 || uses[0] / 3 == uses[1] / 3) continue;
    across[uses[0]] = uses[1];
    across[uses[1]] = uses[0];
  }
  return across;
}

std::vector<std::array<std::uint32_t, 3>> manifoldNeighbours(
    std::span<const TriangleVertices> triangles) {
  const std::vector<std::uint32_t> across = sidesAcross(triangles);
  std::vector<std::array<std::uint32_t, 3>> neighbours(triangles.size());
  for (std::size_t side = 0; side < across.size(); ++side)
    neighbours[side / 3][side % 3] = across[side] == kNoTriangle ? kNoTriangle : across[side] / 3;
  return neighbours;
}

// The last triangle a breadth-first walk from `start` reaches.
std::uint32_t farthestFrom(std::span<const std::array<std::uint32_t, 3>> neighbours,
                           std::uint32_t start) {
  std::vector<char> seen(neighbours.size(), 0);
  std::vector<std::uint32_t> queue{start};
  seen[start] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (std::uint32_t n : neighbours[queue[head]])
      if (n != kNoTriangle && !seen[n]) {
        seen[n] = 1;
        queue.push_back(n);
      }
  return queue.back();
}

// Owner (0 or 1) of each triangle: two breadth-first regions grown from the seeds, the smaller
// one claiming the next triangle, so that they stay of similar size.
std::vector<int> growTwoRegions(std::span<const std::array<std::uint32_t, 3>> neighbours,
                                std::uint32_t seed0, std::uint32_t seed1) {
  std::vector<int> owner(neighbours.size(), -1);
  std::array<std::vector<std::uint32_t>, 2> claimed{{{seed0}, {seed1}}};
  std::array<std::size_t, 2> head{0, 0};  // first claimed triangle that may have free neighbours
  owner[seed0] = 0;
  owner[seed1] = 1;
  auto claimOne = [&](int side) {
    auto& region = claimed[side];
    for (; head[side] < region.size(); ++head[side])
      for (std::uint32_t n : neighbours[region[head[side]]])
        if (n != kNoTriangle && owner[n] < 0) {
          owner[n] = side;
          region.push_back(n);
          return true;
        }
    return false;
  };
  std::array<bool, 2> growing{true, true};
  while (growing[0] || growing[1]) {
    const int side = !growing[0] ? 1
                     : !growing[1] ? 0
                                   : (claimed[1].size() < claimed[0].size() ? 1 : 0);
    growing[side] = claimOne(side);
  }
  // Triangles no seed reaches (the set was not connected) join the smaller region.
  const int smaller = claimed[1].size() < claimed[0].size() ? 1 : 0;
  for (int& o : owner)
    if (o < 0) o = smaller;
  return owner;
}

}  // namespace

std::vector<int> classifyByAngle(const Triangulation& t, std::span<const int> labels,
                                 const ClassifyOptions& options) {
  checkLabels(t, labels);
  const std::size_t count = t.triangles.size();
  std::vector<Vec3> normals(count);
  for (std::uint32_t i = 0; i < count; ++i) normals[i] = triangleNormal(t, i);
  const double minCosine = std::cos(options.angle);
  DisjointSets regions(count);
  joinAcrossManifoldEdges(edgeTable(t.triangles), regions, [&](std::uint32_t a, std::uint32_t b) {
    if (options.includeBoundary && labelOf(labels, a) != labelOf(labels, b)) return false;
    return dot(normals[a], normals[b]) >= minCosine;
  });
  std::vector<int> result = componentLabels(regions, count);
  if (options.forReparametrization) result = splitIntoDisks(t, result);
  return result;
}

namespace {

// The frontier of a breadth-first split zigzags across the triangles; the curve along it is
// remeshed, and its teeth would give short edges there. A triangle with two of its neighbours
// on the other side goes over (the seeds stay), for a few passes.
void smoothSplit(std::span<const std::array<std::uint32_t, 3>> neighbours,
                 std::array<std::uint32_t, 2> seeds, std::vector<int>& owner) {
  constexpr int kPasses = 4;
  for (int pass = 0; pass < kPasses; ++pass) {
    bool changed = false;
    for (std::uint32_t t = 0; t < owner.size(); ++t) {
      if (t == seeds[0] || t == seeds[1]) continue;
      int across = 0;
      for (std::uint32_t n : neighbours[t])
        if (n != kNoTriangle && owner[n] != owner[t]) ++across;
      if (across < 2) continue;
      owner[t] = 1 - owner[t];
      changed = true;
    }
    if (!changed) return;
  }
}

}  // namespace

std::array<std::vector<std::uint32_t>, 2> splitPatch(const Triangulation& t,
                                                     std::span<const std::uint32_t> triangles) {
  std::array<std::vector<std::uint32_t>, 2> halves;
  if (triangles.size() <= 1) {
    halves[0].assign(triangles.begin(), triangles.end());
    return halves;
  }
  const auto neighbours = manifoldNeighbours(gather(t, triangles));
  const std::uint32_t seed0 = farthestFrom(neighbours, 0);
  std::uint32_t seed1 = farthestFrom(neighbours, seed0);
  if (seed1 == seed0) seed1 = seed0 == 0 ? 1 : 0;  // seed0 alone in its component
  std::vector<int> owner = growTwoRegions(neighbours, seed0, seed1);
  smoothSplit(neighbours, {seed0, seed1}, owner);
  for (std::size_t i = 0; i < triangles.size(); ++i) halves[owner[i]].push_back(triangles[i]);
  for (auto& half : halves) std::sort(half.begin(), half.end());
  return halves;
}

PatchShape patchShape(const Triangulation& t, std::span<const std::uint32_t> triangles) {
  const std::vector<TriangleVertices> subset = gather(t, triangles);
  std::vector<std::uint32_t> vertices;
  vertices.reserve(3 * subset.size());
  for (const TriangleVertices& v : subset) vertices.insert(vertices.end(), v.begin(), v.end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  PatchShape shape;
  shape.euler = static_cast<int>(vertices.size()) - static_cast<int>(edgeTable(subset).size()) +
                static_cast<int>(subset.size());
  shape.boundaryLoops = static_cast<int>(boundaryLoops(subset).size());
  return shape;
}

// ---------------------------------------------------------------------------------------------
// Topology: patches, feature edges, curves, points and the loops of the patches.

namespace {

// The edges that become curves, with the patches along each and the feature edges at each
// vertex.
struct FeatureGraph {
  const EdgeTable& table;
  std::vector<std::uint32_t> edges;  // ids in `table`, ascending
  std::vector<std::uint32_t> patchStart, patches;  // feature f: patches[patchStart[f], ...[f+1])
  std::vector<std::uint32_t> vertexStart, atVertex;  // vertex v: atVertex[vertexStart[v], ...]

  std::span<const std::uint32_t> patchesOf(std::uint32_t f) const {
    return std::span(patches).subspan(patchStart[f], patchStart[f + 1] - patchStart[f]);
  }
  std::span<const std::uint32_t> featuresAt(std::uint32_t v) const {
    return std::span(atVertex).subspan(vertexStart[v], vertexStart[v + 1] - vertexStart[v]);
  }
  std::uint32_t otherEnd(std::uint32_t f, std::uint32_t v) const {
    const auto& ends = table.ends[edges[f]];
    return ends[0] == v ? ends[1] : ends[0];
  }
  std::uint32_t featureBetween(std::uint32_t a, std::uint32_t b) const {
    for (std::uint32_t f : featuresAt(a))
      if (otherEnd(f, a) == b) return f;
    return kNoTriangle;
  }
};

std::vector<int> patchComponents(const Triangulation& t, const EdgeTable& edges,
                                 std::span<const int> labels) {
  DisjointSets patches(t.triangles.size());
  joinAcrossManifoldEdges(edges, patches, [&](std::uint32_t a, std::uint32_t b) {
    return labelOf(labels, a) == labelOf(labels, b);
  });
  return componentLabels(patches, t.triangles.size());
}

void indexFeaturesByVertex(FeatureGraph& graph, std::size_t vertexCount) {
  graph.vertexStart.assign(vertexCount + 1, 0);
  for (std::uint32_t e : graph.edges)
    for (std::uint32_t v : graph.table.ends[e]) ++graph.vertexStart[v + 1];
  std::partial_sum(graph.vertexStart.begin(), graph.vertexStart.end(), graph.vertexStart.begin());
  graph.atVertex.resize(graph.vertexStart.back());
  std::vector<std::uint32_t> fill(graph.vertexStart.begin(), graph.vertexStart.end() - 1);
  for (std::uint32_t f = 0; f < graph.edges.size(); ++f)
    for (std::uint32_t v : graph.table.ends[graph.edges[f]]) graph.atVertex[fill[v]++] = f;
}

FeatureGraph featureGraph(const Triangulation& t, const EdgeTable& edges,
                          std::span<const int> patchOf) {
  FeatureGraph graph{edges, {}, {0}, {}, {}, {}};
  std::vector<std::uint32_t> along;
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    if (edges.ends[e][0] == edges.ends[e][1]) continue;
    along.clear();
    for (std::uint32_t use : edges.usesOf(e)) along.push_back(patchOf[use / 3]);
    const std::size_t useCount = along.size();
    std::sort(along.begin(), along.end());
    along.erase(std::unique(along.begin(), along.end()), along.end());
    if (useCount == 2 && along.size() == 1) continue;  // inside a patch
    graph.edges.push_back(e);
    graph.patches.insert(graph.patches.end(), along.begin(), along.end());
    graph.patchStart.push_back(static_cast<std::uint32_t>(graph.patches.size()));
  }
  indexFeaturesByVertex(graph, t.points.size());
  return graph;
}

double turningAngle(const Triangulation& t, std::uint32_t from, std::uint32_t at,
                    std::uint32_t to) {
  const Vec3 in = t.points[at] - t.points[from], out = t.points[to] - t.points[at];
  const double lengths = norm(in) * norm(out);
  if (lengths == 0) return 0;
  return std::acos(std::clamp(dot(in, out) / lengths, -1.0, 1.0));
}

// Vertices where curves end: not on exactly two feature edges, on two along different patches,
// or where the two turn by more than curveAngle.
std::vector<char> curveEnds(const Triangulation& t, const FeatureGraph& graph,
                            double curveAngle) {
  std::vector<char> isEnd(t.points.size(), 0);
  for (std::uint32_t v = 0; v < t.points.size(); ++v) {
    const auto features = graph.featuresAt(v);
    if (features.empty()) continue;
    if (features.size() != 2 ||
        !std::ranges::equal(graph.patchesOf(features[0]), graph.patchesOf(features[1])))
      isEnd[v] = 1;
    else if (turningAngle(t, graph.otherEnd(features[0], v), v, graph.otherEnd(features[1], v)) >
             curveAngle)
      isEnd[v] = 1;
  }
  return isEnd;
}

// Follows feature edges from `start` along `first` to the next curve end, or back to `start`.
DiscreteTopology::Curve traceCurve(const FeatureGraph& graph, std::span<const char> isEnd,
                                   std::uint32_t start, std::uint32_t first,
                                   std::vector<char>& used) {
  DiscreteTopology::Curve curve{{start}};
  std::uint32_t at = start, f = first;
  while (true) {
    used[f] = 1;
    at = graph.otherEnd(f, at);
    curve.vertices.push_back(at);
    if (isEnd[at] || at == start) break;
    const auto features = graph.featuresAt(at);  // two, since `at` is no end
    f = features[0] == f ? features[1] : features[0];
    if (used[f]) break;
  }
  return curve;
}

void traceCurves(const Triangulation& t, const FeatureGraph& graph, double curveAngle,
                 DiscreteTopology& topology) {
  const std::vector<char> isEnd = curveEnds(t, graph, curveAngle);
  std::vector<char> used(graph.edges.size(), 0);
  for (std::uint32_t v = 0; v < t.points.size(); ++v) {
    if (!isEnd[v]) continue;
    topology.points.push_back(v);
    for (std::uint32_t f : graph.featuresAt(v))
      if (!used[f]) topology.curves.push_back(traceCurve(graph, isEnd, v, f, used));
  }
  // What remains are closed chains without an end. Edges are sorted by their smaller vertex, so
  // the first unused one starts at its chain's smallest vertex.
  for (std::uint32_t f = 0; f < graph.edges.size(); ++f) {
    if (used[f]) continue;
    const std::uint32_t smallest = graph.table.ends[graph.edges[f]][0];
    topology.points.push_back(smallest);
    topology.curves.push_back(traceCurve(graph, isEnd, smallest, f, used));
  }
  std::sort(topology.points.begin(), topology.points.end());
}

double curveLength(const Triangulation& t, const DiscreteTopology::Curve& curve) {
  double length = 0;
  for (std::size_t i = 1; i < curve.vertices.size(); ++i)
    length += distance(t.points[curve.vertices[i - 1]], t.points[curve.vertices[i]]);
  return length;
}

// Chains signed curves into closed loops (a curve's end to the next one's start).
std::vector<std::vector<int>> chainLoops(std::span<const int> signedCurves,
                                         const std::vector<DiscreteTopology::Curve>& curves) {
  auto startOf = [&](int c) {
    const auto& v = curves[std::abs(c) - 1].vertices;
    return c > 0 ? v.front() : v.back();
  };
  auto endOf = [&](int c) { return startOf(-c); };
  std::vector<std::uint32_t> byStart(signedCurves.size());
  std::iota(byStart.begin(), byStart.end(), 0u);
  std::stable_sort(byStart.begin(), byStart.end(), [&](std::uint32_t a, std::uint32_t b) {
    return startOf(signedCurves[a]) < startOf(signedCurves[b]);
  });
  std::vector<char> used(signedCurves.size(), 0);
  auto nextFrom = [&](std::uint32_t vertex) -> std::int64_t {
    auto it = std::lower_bound(byStart.begin(), byStart.end(), vertex,
                               [&](std::uint32_t i, std::uint32_t v) {
                                 return startOf(signedCurves[i]) < v;
                               });
    for (; it != byStart.end() && startOf(signedCurves[*it]) == vertex; ++it)
      if (!used[*it]) return *it;
    return -1;
  };
  std::vector<std::vector<int>> loops;
  for (std::size_t first = 0; first < signedCurves.size(); ++first) {
    if (used[first]) continue;
    used[first] = 1;
    std::vector<int> loop{signedCurves[first]};
    const std::uint32_t start = startOf(signedCurves[first]);
    for (std::uint32_t at = endOf(signedCurves[first]); at != start;) {
      const std::int64_t next = nextFrom(at);
      if (next < 0) break;  // open only past a non-manifold or inconsistently oriented edge
      used[next] = 1;
      loop.push_back(signedCurves[next]);
      at = endOf(signedCurves[next]);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The signed curves that bound each patch: a curve is run forward by a patch whose triangle
// runs the curve's first edge from its first vertex to its second.
std::vector<std::vector<int>> boundingCurves(const Triangulation& t, const FeatureGraph& graph,
                                             std::span<const int> patchOf,
                                             const std::vector<DiscreteTopology::Curve>& curves,
                                             std::size_t patchCount) {
  std::vector<std::vector<int>> bounding(patchCount);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const std::uint32_t v0 = curves[c].vertices[0], v1 = curves[c].vertices[1];
    const std::uint32_t edge = graph.edges[graph.featureBetween(v0, v1)];
    for (std::uint32_t use : graph.table.usesOf(edge)) {
      const int sign = useFrom(t.triangles, use) == v0 ? 1 : -1;
      bounding[patchOf[use / 3]].push_back(sign * static_cast<int>(c + 1));
    }
  }
  return bounding;
}

void addPatchLoops(const Triangulation& t, const FeatureGraph& graph,
                   std::span<const int> patchOf, DiscreteTopology& topology) {
  std::vector<double> lengths(topology.curves.size());
  for (std::size_t c = 0; c < lengths.size(); ++c) lengths[c] = curveLength(t, topology.curves[c]);
  auto loopLength = [&](const std::vector<int>& loop) {
    double length = 0;
    for (int c : loop) length += lengths[std::abs(c) - 1];
    return length;
  };
  const auto bounding =
      boundingCurves(t, graph, patchOf, topology.curves, topology.patches.size());
  for (std::size_t p = 0; p < topology.patches.size(); ++p) {
    auto& loops = topology.patches[p].loops;
    loops = chainLoops(bounding[p], topology.curves);
    std::stable_sort(loops.begin(), loops.end(), [&](const auto& a, const auto& b) {
      return loopLength(a) > loopLength(b);
    });
  }
}

}  // namespace

DiscreteTopology buildTopology(const Triangulation& t, std::span<const int> labels,
                               double curveAngle) {
  checkLabels(t, labels);
  const EdgeTable edges = edgeTable(t.triangles);
  const std::vector<int> patchOf = patchComponents(t, edges, labels);
  DiscreteTopology topology;
  for (auto& triangles : groupByLabel(patchOf))
    topology.patches.push_back({std::move(triangles), {}});
  const FeatureGraph graph = featureGraph(t, edges, patchOf);
  traceCurves(t, graph, curveAngle, topology);
  addPatchLoops(t, graph, patchOf, topology);
  return topology;
}

// ---------------------------------------------------------------------------------------------
// Repairs.

namespace {

// For each point, the first point at the same place.
std::vector<std::uint32_t> exactTargets(std::span<const Vec3> points) {
  std::vector<std::uint32_t> target(points.size());
  std::iota(target.begin(), target.end(), 0u);
  std::vector<std::uint32_t> order(target);
  auto key = [&](std::uint32_t i) {
    return std::make_tuple(points[i].x, points[i].y, points[i].z, i);
  };
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return key(a) < key(b); });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Vec3 a = points[order[k - 1]], b = points[order[k]];
    if (a == b) target[order[k]] = target[order[k - 1]];
  }
  return target;
}

using Cell = std::array<std::int64_t, 3>;

std::uint64_t cellHash(const Cell& cell) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::int64_t x : cell) h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ull;
  return h;
}

// Points grouped by cells of side `size`, and for each cell the non-empty cells around it
// (itself included): points at most `size` apart are in the same or in touching cells. Cells
// are found by hash; a collision only adds candidates.
struct CellGrid {
  std::vector<std::uint32_t> points;          // cell by cell
  std::vector<std::uint32_t> cellStart;       // cell c: points[cellStart[c], cellStart[c + 1])
  std::vector<std::uint32_t> cellOfPoint;
  std::vector<std::uint32_t> nearStart, near;  // cell c: near[nearStart[c], nearStart[c + 1])
};

CellGrid cellGrid(std::span<const Vec3> points, double size) {
  auto cellOf = [&](Vec3 p) {
    auto index = [&](double x) {
      return static_cast<std::int64_t>(std::clamp(std::floor(x / size), -1e15, 1e15));
    };
    return Cell{index(p.x), index(p.y), index(p.z)};
  };
  struct Entry {
    std::uint64_t hash;
    Cell cell;
    std::uint32_t point;
  };
  std::vector<Entry> entries(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const Cell cell = cellOf(points[i]);
    entries[i] = {cellHash(cell), cell, i};
  }
  auto key = [](const Entry& e) { return std::tie(e.hash, e.cell, e.point); };
  std::sort(entries.begin(), entries.end(), [&](auto& a, auto& b) { return key(a) < key(b); });
  CellGrid grid;
  grid.cellOfPoint.resize(points.size());
  std::vector<Cell> cells;
  std::vector<std::uint64_t> hashes;
  for (std::uint32_t k = 0; k < entries.size(); ++k) {
    if (k == 0 || entries[k].cell != entries[k - 1].cell) {
      cells.push_back(entries[k].cell);
      hashes.push_back(entries[k].hash);
      grid.cellStart.push_back(k);
    }
    grid.points.push_back(entries[k].point);
    grid.cellOfPoint[entries[k].point] = static_cast<std::uint32_t>(cells.size() - 1);
  }
  grid.cellStart.push_back(static_cast<std::uint32_t>(entries.size()));
  std::unordered_map<std::uint64_t, std::uint32_t> firstWithHash(cells.size());
  for (auto c = static_cast<std::uint32_t>(cells.size()); c-- > 0;) firstWithHash[hashes[c]] = c;
  grid.nearStart.push_back(0);
  for (const Cell& cell : cells) {
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const std::uint64_t h = cellHash({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          const auto found = firstWithHash.find(h);
          if (found == firstWithHash.end()) continue;
          for (std::uint32_t d = found->second; d < cells.size() && hashes[d] == h; ++d)
            grid.near.push_back(d);
        }
    grid.nearStart.push_back(static_cast<std::uint32_t>(grid.near.size()));
  }
  return grid;
}

// For each point, the first point at most `tolerance` from it that is its own target, so that
// merges do not chain.
std::vector<std::uint32_t> nearTargets(std::span<const Vec3> points, double tolerance) {
  const CellGrid grid = cellGrid(points, tolerance);
  std::vector<std::uint32_t> target(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    std::uint32_t best = i;
    const std::uint32_t cell = grid.cellOfPoint[i];
    for (std::uint32_t n = grid.nearStart[cell]; n < grid.nearStart[cell + 1]; ++n) {
      const std::uint32_t near = grid.near[n];
      for (std::uint32_t k = grid.cellStart[near]; k < grid.cellStart[near + 1]; ++k) {
        const std::uint32_t j = grid.points[k];
        if (j < best && target[j] == j && distance(points[i], points[j]) <= tolerance) best = j;
      }
    }
    target[i] = best;
  }
  return target;
}

// Drops triangles with a repeated vertex and all but the first of triangles on the same
// three vertices.
void dropDegenerateAndDuplicateTriangles(std::vector<TriangleVertices>& triangles,
                                         std::vector<int>* labels) {
  std::vector<std::pair<TriangleVertices, std::uint32_t>> sorted;
  sorted.reserve(triangles.size());
  for (std::uint32_t i = 0; i < triangles.size(); ++i) {
    TriangleVertices v = triangles[i];
    std::sort(v.begin(), v.end());
    if (v[0] != v[1] && v[1] != v[2]) sorted.emplace_back(v, i);
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> keep(triangles.size(), 0);
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (i == 0 || sorted[i].first != sorted[i - 1].first) keep[sorted[i].second] = 1;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (!keep[i]) continue;
    if (labels) (*labels)[kept] = (*labels)[i];
    triangles[kept++] = triangles[i];
  }
  triangles.resize(kept);
  if (labels) labels->resize(kept);
}

}  // namespace

std::size_t mergeDuplicateVertices(Triangulation& t, double tolerance, std::vector<int>* labels) {
  const std::vector<std::uint32_t> target =
      tolerance > 0 ? nearTargets(t.points, tolerance) : exactTargets(t.points);
  std::vector<std::uint32_t> newIndex(t.points.size());
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < t.points.size(); ++i) {
    if (target[i] == i) {
      newIndex[i] = static_cast<std::uint32_t>(kept.size());
      kept.push_back(t.points[i]);
    } else {
      newIndex[i] = newIndex[target[i]];  // target[i] < i
    }
  }
  const std::size_t merged = t.points.size() - kept.size();
  t.points = std::move(kept);
  for (TriangleVertices& triangle : t.triangles)
    for (std::uint32_t& v : triangle) v = newIndex[v];
  dropDegenerateAndDuplicateTriangles(t.triangles, labels);
  return merged;
}

std::size_t orientConsistently(Triangulation& t) {
  const std::vector<std::uint32_t> across = sidesAcross(t.triangles);
  std::vector<char> flip(t.triangles.size(), 0), seen(t.triangles.size(), 0);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t seed = 0; seed < t.triangles.size(); ++seed) {
    if (seen[seed]) continue;
    seen[seed] = 1;
    queue.assign({seed});
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t at = queue[head];
      for (std::uint32_t side = 3 * at; side < 3 * at + 3; ++side) {
        const std::uint32_t other = across[side];
        if (other == kNoTriangle || seen[other / 3]) continue;
        // Two sides that run their edge the same way need opposite flips.
        const bool sameWay = useFrom(t.triangles, side) == useFrom(t.triangles, other);
        flip[other / 3] = flip[at] ^ static_cast<char>(sameWay);
        seen[other / 3] = 1;
        queue.push_back(other / 3);
      }
    }
  }
  std::size_t flipped = 0;
  for (std::size_t i = 0; i < t.triangles.size(); ++i)
    if (flip[i]) {
      std::swap(t.triangles[i][1], t.triangles[i][2]);
      ++flipped;
    }
  return flipped;
}

}  // namespace geomesh
