// pairLeftoverTriangles (declared in recombine.h): the triangles recombination left alone,
// joined in pairs by splitting the elements on a path between them into quadrangles.
#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mesh/quads/recombine.h"

namespace geomesh {
namespace {

// An element of the surface: its block (triangles or quadrangles) and its index there.
struct Face {
  ElementType type;
  std::uint32_t index;
};

struct FaceGraph {
  std::vector<std::vector<NodeIndex>> corners;  // by face, in the element's order
  std::vector<Face> faces;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> bySide;
};

FaceGraph faceGraph(const EntityMesh& em) {
  FaceGraph g;
  for (ElementType type : {ElementType::Triangle3, ElementType::Quad4})
    if (const ElementBlock* block = em.findBlock(type))
      for (std::uint32_t e = 0; e < block->size(); ++e) {
        const auto n = block->element(e);
        const auto face = static_cast<std::uint32_t>(g.faces.size());
        g.faces.push_back({type, e});
        g.corners.emplace_back(n.begin(), n.end());
        for (std::size_t k = 0; k < n.size(); ++k)
          g.bySide[edgeKey(n[k], n[(k + 1) % n.size()])].push_back(face);
      }
  return g;
}

// The faces on a shortest path from face `from` to the nearest other triangle, across sides
// two faces share and that are not kept; empty if none.
std::vector<std::uint32_t> pathToTriangle(const FaceGraph& g, std::uint32_t from,
                                          const std::vector<std::uint64_t>& kept) {
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> parent(g.faces.size(), kNone);
  std::deque<std::uint32_t> queue{from};
  parent[from] = from;
  while (!queue.empty()) {
    const std::uint32_t f = queue.front();
    queue.pop_front();
    if (f != from && g.faces[f].type == ElementType::Triangle3) {
      std::vector<std::uint32_t> path{f};
      while (path.back() != from) path.push_back(parent[path.back()]);
      std::reverse(path.begin(), path.end());
      return path;
    }
    const std::vector<NodeIndex>& c = g.corners[f];
    for (std::size_t k = 0; k < c.size(); ++k) {
      const std::uint64_t key = edgeKey(c[k], c[(k + 1) % c.size()]);
      if (std::binary_search(kept.begin(), kept.end(), key)) continue;
      const std::vector<std::uint32_t>& two = g.bySide.at(key);
      if (two.size() != 2) continue;
      for (std::uint32_t next : two)
        if (parent[next] == kNone) parent[next] = f, queue.push_back(next);
    }
  }
  return {};
}

// New nodes planned on the surface before any is added: node indices from the mesh's next
// one on, so that the quadrangles are checked before the mesh changes.
class NodePlan {
 public:
  NodePlan(const SurfaceGeometry& g, const Mesh& mesh) : g_(g), mesh_(mesh) {}

  NodeIndex add(Vec3 near, double size) {
    const Vec2 uv = g_.project(near);
    uv_.push_back(uv);
    xyz_.push_back(g_.point(uv));
    size_.push_back(size);
    return static_cast<NodeIndex>(mesh_.nodeCount() + xyz_.size() - 1);
  }
  Vec3 position(NodeIndex n) const {
    return n < mesh_.nodeCount() ? mesh_.node(n) : xyz_[n - mesh_.nodeCount()];
  }
  double size(NodeIndex n) const {
    return n < mesh_.nodeCount() ? mesh_.nodeSize(n) : size_[n - mesh_.nodeCount()];
  }
  // The middle of the segment from a to b, on the surface.
  NodeIndex middle(NodeIndex a, NodeIndex b) {
    return add((position(a) + position(b)) / 2, (size(a) + size(b)) / 2);
  }
  // A node at the centre of the polygon, on the surface.
  NodeIndex centre(const std::vector<NodeIndex>& polygon) {
    Vec3 sum{0, 0, 0};
    double sizes = 0;
    for (NodeIndex n : polygon) sum = sum + position(n), sizes += size(n);
    const double count = static_cast<double>(polygon.size());
    return add(sum / count, sizes / count);
  }
  // Forgets the node planned last.
  void dropLast() {
    xyz_.pop_back(), uv_.pop_back(), size_.pop_back();
  }
  void commit(Mesh& mesh, EntityMesh& em) const {
    for (std::size_t k = 0; k < xyz_.size(); ++k) {
      const NodeIndex n = mesh.addNode(xyz_[k]);
      mesh.setNodeSize(n, size_[k]);
      em.nodes.push_back(n);
      em.parametric.insert(em.parametric.end(), {uv_[k].u, uv_[k].v});
    }
  }

 private:
  const SurfaceGeometry& g_;
  const Mesh& mesh_;
  std::vector<Vec3> xyz_;
  std::vector<Vec2> uv_;
  std::vector<double> size_;
};

// The quadrangles replacing a quadrangle with two split sides, given its polygon (its corners
// with the middle nodes inserted) and which positions are middle nodes: by the segment
// joining the middles of opposite sides, or around a new centre node for adjacent ones.
std::vector<std::array<NodeIndex, 4>> splitFace(NodePlan& plan,
                                                const std::vector<NodeIndex>& polygon,
                                                const std::vector<bool>& middle) {
  const std::size_t n = polygon.size();
  auto from = [&](std::size_t first) {
    return [&, first](std::size_t k) { return polygon[(first + k) % n]; };
  };
  for (std::size_t first = 0; first < n; ++first)
    if (middle[(first + 1) % n] && middle[(first + 4) % n]) {
      const auto at = from(first);
      return {{at(0), at(1), at(4), at(5)}, {at(1), at(2), at(3), at(4)}};
    }
  std::size_t first = 0;
  while (!(middle[(first + 1) % n] && middle[(first + 3) % n])) ++first;
  const auto at = from(first);
  const NodeIndex o = plan.centre(polygon);
  return {{at(0), at(1), o, at(5)}, {at(1), at(2), at(3), o}, {o, at(3), at(4), at(5)}};
}

// Whether the quadrangle is convex on the surface, turning along `normal`, with no corner
// nearly straight.
bool isConvex(const NodePlan& plan, const std::array<NodeIndex, 4>& q, Vec3 normal) {
  return quadAngleQuality(plan.position(q[0]), plan.position(q[1]), plan.position(q[2]),
                          plan.position(q[3]), normal) > kMinQuadQuality;
}

// The polygon of faces a and b, which share one side: a's corners from the end of that side
// round to its start, then b's corners between.
std::vector<NodeIndex> merged(const std::vector<NodeIndex>& a, const std::vector<NodeIndex>& b) {
  const std::size_t na = a.size(), nb = b.size();
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < nb; ++j)
      if (a[i] == b[(j + 1) % nb] && a[(i + 1) % na] == b[j]) {
        std::vector<NodeIndex> polygon;
        for (std::size_t k = 1; k <= na; ++k) polygon.push_back(a[(i + k) % na]);
        for (std::size_t k = 2; k < nb; ++k) polygon.push_back(b[(j + k) % nb]);
        return polygon;
      }
  return {};
}

// Inserts the middle nodes of the polygon's sides found in `middleOf` after each side's start.
void insertMiddles(const std::unordered_map<std::uint64_t, NodeIndex>& middleOf,
                   std::vector<NodeIndex>& polygon, std::vector<bool>& middle) {
  std::vector<NodeIndex> out;
  middle.clear();
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    out.push_back(polygon[k]), middle.push_back(false);
    const auto it = middleOf.find(edgeKey(polygon[k], polygon[(k + 1) % polygon.size()]));
    if (it != middleOf.end()) out.push_back(it->second), middle.push_back(true);
  }
  polygon = std::move(out);
}

// A hexagon split into quadrangles: two, along a diagonal (through its middle node if it has
// one), or three around a new centre node joined to every other corner; the best of these by
// the worst corner angle. nullopt when none gives convex quadrangles with no corner nearly
// straight.
std::optional<std::vector<std::array<NodeIndex, 4>>> cutHexagon(
    NodePlan& plan, const std::vector<NodeIndex>& h, const std::vector<bool>& middle,
    Vec3 normal) {
  auto quality = [&](const std::array<NodeIndex, 4>& q) {
    return quadAngleQuality(plan.position(q[0]), plan.position(q[1]), plan.position(q[2]),
                            plan.position(q[3]), normal);
  };
  std::optional<std::vector<std::array<NodeIndex, 4>>> best;
  double bestQuality = kMinQuadQuality;
  auto consider = [&](std::vector<std::array<NodeIndex, 4>> quads) {
    double worst = 1;
    for (const auto& q : quads) worst = std::min(worst, quality(q));
    if (worst > bestQuality) best = std::move(quads), bestQuality = worst;
  };
  const bool hasMiddle = std::count(middle.begin(), middle.end(), true) > 0;
  for (std::size_t i = 0; i < 3; ++i)
    if (!hasMiddle || middle[i] || middle[i + 3])
      consider({{h[i], h[i + 1], h[i + 2], h[i + 3]}, {h[i + 3], h[(i + 4) % 6], h[(i + 5) % 6], h[i]}});
  // A middle node must be a corner of the quadrangles around the centre, not a side's middle.
  const NodeIndex o = plan.centre(h);
  for (std::size_t i = 0; i < 2; ++i)
    if (!hasMiddle || middle[i] || middle[i + 2] || middle[i + 4])
      consider({{h[i], h[i + 1], h[i + 2], o}, {h[i + 2], h[i + 3], h[i + 4], o},
                {h[i + 4], h[(i + 5) % 6], h[i], o}});
  if (!best || best->size() == 2) plan.dropLast();
  return best;
}

Vec3 normalAt(const SurfaceGeometry& g, const NodePlan& plan, const std::vector<NodeIndex>& polygon,
              double orientation) {
  Vec3 centre{0, 0, 0};
  for (NodeIndex n : polygon) centre = centre + plan.position(n);
  const SurfaceDerivatives d =
      g.firstDerivatives(g.project(centre / static_cast<double>(polygon.size())));
  return orientation * cross(d.du, d.dv);
}

// The quadrangles replacing the faces of `path` (a triangle, quadrangles, a triangle): each
// end triangle merges with its neighbour on the path into a pentagon, the sides the
// quadrangles between share get middle nodes, so that every piece has an even number of
// corners: the pentagons become hexagons cut in two, the quadrangles between are split (see
// splitFace). nullopt when a piece would not be convex.
std::optional<std::vector<std::array<NodeIndex, 4>>> splitPath(
    const SurfaceGeometry& g, NodePlan& plan, const FaceGraph& graph,
    const std::vector<std::uint32_t>& path, double orientation) {
  const std::size_t n = path.size();
  if (n < 3) return std::nullopt;  // two neighbours: blossom found their quadrangle not convex
  std::unordered_map<std::uint64_t, NodeIndex> middleOf;
  for (std::size_t i = 1; i + 2 < n; ++i) {
    const std::vector<NodeIndex>& c = graph.corners[path[i]];
    for (std::size_t k = 0; k < c.size(); ++k) {
      const NodeIndex a = c[k], b = c[(k + 1) % c.size()];
      const std::vector<std::uint32_t>& two = graph.bySide.at(edgeKey(a, b));
      if (std::find(two.begin(), two.end(), path[i + 1]) != two.end())
        middleOf[edgeKey(a, b)] = plan.middle(a, b);
    }
  }
  std::vector<std::vector<NodeIndex>> pieces;
  if (n == 3) {
    pieces.push_back(merged(merged(graph.corners[path[0]], graph.corners[path[1]]),
                            graph.corners[path[2]]));
  } else {
    pieces.push_back(merged(graph.corners[path[0]], graph.corners[path[1]]));
    for (std::size_t i = 2; i + 2 < n; ++i) pieces.push_back(graph.corners[path[i]]);
    pieces.push_back(merged(graph.corners[path[n - 2]], graph.corners[path[n - 1]]));
  }
  std::vector<std::array<NodeIndex, 4>> quads;
  for (std::vector<NodeIndex> polygon : pieces) {
    std::vector<bool> middle;
    insertMiddles(middleOf, polygon, middle);
    const Vec3 normal = normalAt(g, plan, polygon, orientation);
    if (std::count(middle.begin(), middle.end(), true) <= 1) {  // a hexagon
      const auto cut = cutHexagon(plan, polygon, middle, normal);
      if (!cut) return std::nullopt;
      quads.insert(quads.end(), cut->begin(), cut->end());
      continue;
    }
    for (const auto& q : splitFace(plan, polygon, middle)) {
      if (!isConvex(plan, q, normal)) return std::nullopt;
      quads.push_back(q);
    }
  }
  return quads;
}

// +1 when the surface's elements turn along du x dv, -1 when against (its first triangle).
double orientationOf(const SurfaceGeometry& g, const Mesh& mesh, const EntityMesh& em) {
  const ElementBlock* t = em.findBlock(ElementType::Triangle3);
  const auto n = t->element(0);
  const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]);
  const SurfaceDerivatives d = g.firstDerivatives(g.project((a + b + c) / 3));
  return dot(cross(b - a, c - a), cross(d.du, d.dv)) > 0 ? 1 : -1;
}

// Four triangles left around a node of the surface's own that nothing else uses: the node
// goes, and the four become the quadrangle around it when it is convex (a coarse square cut
// from its centre recombines into one quadrangle). Returns the quadrangles made.
std::size_t collapseDiamonds(const SurfaceGeometry& g, const Mesh& mesh, EntityMesh& em,
                             double orientation) {
  ElementBlock* triangles = nullptr;
  for (ElementBlock& b : em.blocks)
    if (b.type == ElementType::Triangle3) triangles = &b;
  if (!triangles) return 0;
  std::unordered_map<NodeIndex, std::vector<std::uint32_t>> around;
  for (std::uint32_t t = 0; t < triangles->size(); ++t)
    for (NodeIndex n : triangles->element(t)) around[n].push_back(t);
  std::unordered_map<NodeIndex, int> usesElsewhere;
  for (const ElementBlock& b : em.blocks)
    if (b.type != ElementType::Triangle3)
      for (NodeIndex n : b.nodes) ++usesElsewhere[n];
  std::vector<std::uint8_t> gone(triangles->size(), 0);
  std::vector<NodeIndex> quads;
  std::unordered_set<NodeIndex> dropped;
  for (std::size_t k = 0; k < em.nodes.size(); ++k) {
    const NodeIndex o = em.nodes[k];
    const auto it = around.find(o);
    if (it == around.end() || it->second.size() != 4 || usesElsewhere.contains(o)) continue;
    if (std::any_of(it->second.begin(), it->second.end(), [&](std::uint32_t t) { return gone[t]; }))
      continue;
    // Each triangle (o, a, b) in its turning order gives the side a -> b of the outline.
    std::map<NodeIndex, NodeIndex> next;
    for (std::uint32_t t : it->second) {
      const auto n = triangles->element(t);
      const int at = static_cast<int>(std::find(n.begin(), n.end(), o) - n.begin());
      next[n[(at + 1) % 3]] = n[(at + 2) % 3];
    }
    if (next.size() != 4) continue;
    std::array<NodeIndex, 4> q{next.begin()->first, 0, 0, 0};
    for (int i = 1; i < 4; ++i) q[i] = next[q[i - 1]];
    if (next[q[3]] != q[0]) continue;
    const Vec3 c = mesh.node(o);
    const SurfaceDerivatives d = g.firstDerivatives(g.project(c));
    if (!(quadAngleQuality(mesh.node(q[0]), mesh.node(q[1]), mesh.node(q[2]), mesh.node(q[3]),
                           orientation * cross(d.du, d.dv)) > kMinQuadQuality))
      continue;
    for (std::uint32_t t : it->second) gone[t] = 1;
    quads.insert(quads.end(), q.begin(), q.end());
    dropped.insert(o);
  }
  if (quads.empty()) return 0;
  std::vector<NodeIndex> kept;
  for (std::uint32_t t = 0; t < triangles->size(); ++t)
    if (!gone[t]) kept.insert(kept.end(), triangles->element(t).begin(), triangles->element(t).end());
  triangles->nodes = std::move(kept);
  ElementBlock& block = em.block(ElementType::Quad4);
  block.nodes.insert(block.nodes.end(), quads.begin(), quads.end());
  dropOwnNodes(em, dropped);
  return quads.size() / 4;
}


}  // namespace

std::size_t pairLeftoverTriangles(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em,
                                  const std::vector<std::uint64_t>& keptEdges) {
  std::size_t paired = 0;
  if (const ElementBlock* t = em.findBlock(ElementType::Triangle3); t && t->size() >= 4)
    paired += collapseDiamonds(g, mesh, em, orientationOf(g, mesh, em));
  // Each pass joins one pair; a pair that cannot be joined ends the work.
  while (true) {
    const ElementBlock* triangles = em.findBlock(ElementType::Triangle3);
    if (!triangles || triangles->size() < 2 || !em.findBlock(ElementType::Quad4)) break;
    const FaceGraph graph = faceGraph(em);
    const double orientation = orientationOf(g, mesh, em);
    std::optional<std::vector<std::array<NodeIndex, 4>>> quads;
    std::vector<std::uint32_t> path;
    std::optional<NodePlan> plan;
    for (std::uint32_t start = 0; start < triangles->size() && !quads; ++start) {
      path = pathToTriangle(graph, start, keptEdges);
      plan.emplace(g, mesh);
      if (!path.empty()) quads = splitPath(g, *plan, graph, path, orientation);
    }
    if (!quads) break;
    plan->commit(mesh, em);
    std::vector<std::uint8_t> onPath(graph.faces.size(), 0);
    for (std::uint32_t f : path) onPath[f] = 1;
    ElementBlock keptTriangles{ElementType::Triangle3, {}}, keptQuads{ElementType::Quad4, {}};
    for (std::uint32_t f = 0; f < graph.faces.size(); ++f) {
      if (onPath[f]) continue;
      ElementBlock& to = graph.faces[f].type == ElementType::Triangle3 ? keptTriangles : keptQuads;
      to.nodes.insert(to.nodes.end(), graph.corners[f].begin(), graph.corners[f].end());
    }
    for (const auto& q : *quads) keptQuads.nodes.insert(keptQuads.nodes.end(), q.begin(), q.end());
    em.blocks.erase(std::remove_if(em.blocks.begin(), em.blocks.end(),
                                   [](const ElementBlock& b) {
                                     return b.type == ElementType::Triangle3 ||
                                            b.type == ElementType::Quad4;
                                   }),
                    em.blocks.end());
    if (!keptTriangles.nodes.empty()) em.blocks.push_back(std::move(keptTriangles));
    em.blocks.push_back(std::move(keptQuads));
    ++paired;
  }
  return paired;
}

void dropOwnNodes(EntityMesh& em, const std::unordered_set<NodeIndex>& dropped) {
  em.blocks.erase(std::remove_if(em.blocks.begin(), em.blocks.end(),
                                 [](const ElementBlock& b) { return b.nodes.empty(); }),
                  em.blocks.end());
  const bool withParameters = em.parametric.size() == 2 * em.nodes.size();
  std::vector<NodeIndex> nodes;
  std::vector<double> parametric;
  for (std::size_t k = 0; k < em.nodes.size(); ++k) {
    if (dropped.contains(em.nodes[k])) continue;
    nodes.push_back(em.nodes[k]);
    if (withParameters)
      parametric.insert(parametric.end(), {em.parametric[2 * k], em.parametric[2 * k + 1]});
  }
  em.nodes = std::move(nodes);
  em.parametric = std::move(parametric);
}

}  // namespace geomesh
