// The first-order view of high-order elements, and the check of the nodes inside their edges.
#include "mesh/checks/high_order_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>

#include "mesh/high_order/reference_element.h"

namespace geomesh {
namespace {

// An edge of an element type: its two corners (element vertex indices) and the indices of the
// element's nodes inside it, in order from the first corner to the second.
struct TypeEdge {
  int a = 0, b = 0;
  std::vector<int> inside;
};

std::vector<TypeEdge> buildTypeEdges(ElementType type) {
  std::vector<TypeEdge> edges;
  const ElementFamily f = family(type);
  if (dimension(f) == 0) return edges;
  // The family's edges, read off its complete second-order element (one node per edge), so
  // that first-order types get them too.
  for (const NodePlace& p : referenceElement(*elementTypeOf(f, 2)).places)
    if (p.kind == NodePlace::Edge) edges.push_back({p.corners[0], p.corners[1], {}});
  const std::vector<NodePlace>& places = referenceElement(type).places;
  for (TypeEdge& e : edges) {
    std::vector<std::pair<int, int>> steps;  // (lattice steps from corner a, node)
    for (std::size_t n = 0; n < places.size(); ++n) {
      const NodePlace& p = places[n];
      if (p.kind != NodePlace::Edge) continue;
      const int node = static_cast<int>(n);
      if (p.corners[0] == e.a && p.corners[1] == e.b) steps.emplace_back(p.weights[1], node);
      if (p.corners[0] == e.b && p.corners[1] == e.a) steps.emplace_back(p.weights[0], node);
    }
    std::sort(steps.begin(), steps.end());
    for (const auto& [step, node] : steps) e.inside.push_back(node);
  }
  return edges;
}

const std::vector<TypeEdge>& typeEdges(ElementType type) {
  static const std::map<ElementType, std::vector<TypeEdge>> all = [] {
    std::map<ElementType, std::vector<TypeEdge>> edges;
    for (const ElementTypeInfo& info : kElementTypes) edges[info.type] = buildTypeEdges(info.type);
    return edges;
  }();
  return all.at(type);
}

constexpr std::size_t kMaxInside = 3;  // an edge of order 4
constexpr NodeIndex kNone = ~NodeIndex{0};

// One element's view of one edge: the edge's corner nodes as a key (smaller in the high half),
// the nodes inside it from the smaller corner node on, and the element's entity.
struct EdgeRecord {
  std::uint64_t key = 0;
  std::array<NodeIndex, kMaxInside> inside{kNone, kNone, kNone};
  std::size_t entity = 0;  // index into the list of entities

  auto tied() const { return std::tie(key, inside, entity); }
  bool operator<(const EdgeRecord& o) const { return tied() < o.tied(); }
};

std::string nodeList(const std::array<NodeIndex, kMaxInside>& nodes) {
  std::string text;
  for (NodeIndex n : nodes)
    if (n != kNone) text += (text.empty() ? "" : " ") + std::to_string(n + 1);
  return "(" + text + ")";
}

bool inRange(const Mesh& mesh, std::span<const NodeIndex> nodes) {
  return std::all_of(nodes.begin(), nodes.end(),
                     [&](NodeIndex n) { return n < mesh.nodeCount(); });
}

void addRecords(const ElementBlock& block, std::size_t entity, const Mesh& mesh,
                std::vector<EdgeRecord>& records) {
  const std::vector<TypeEdge>& edges = typeEdges(block.type);
  for (std::size_t e = 0; e < block.size(); ++e) {
    const auto n = block.element(e);
    if (!inRange(mesh, n)) continue;  // reported by the index check
    for (const TypeEdge& edge : edges) {
      const NodeIndex a = n[edge.a], b = n[edge.b];
      EdgeRecord r;
      r.key = a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
      r.entity = entity;
      const std::size_t count = std::min(edge.inside.size(), kMaxInside);
      for (std::size_t k = 0; k < count; ++k)
        r.inside[k] = n[edge.inside[a < b ? k : count - 1 - k]];
      records.push_back(r);
    }
  }
}

}  // namespace

bool hasHighOrderElements(const Mesh& mesh) {
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& block : em.blocks)
      if (order(block.type) > 1 && block.size() > 0) return true;
  return false;
}

std::map<EntityId, EntityMesh> cornerMeshes(const Mesh& mesh) {
  std::map<EntityId, EntityMesh> out;
  for (const auto& [id, em] : mesh.entities()) {
    const bool highOrder = std::any_of(em.blocks.begin(), em.blocks.end(),
                                       [](const ElementBlock& b) { return order(b.type) > 1; });
    if (!highOrder) continue;
    EntityMesh corners;
    corners.entity = em.entity;
    corners.nodes = em.nodes;
    corners.parametric = em.parametric;
    corners.periodic = em.periodic;
    for (const ElementBlock& block : em.blocks) {
      ElementBlock& linear = corners.block(linearType(family(block.type)));
      const std::size_t count = static_cast<std::size_t>(vertexCount(block.type));
      for (std::size_t e = 0; e < block.size(); ++e) {
        const auto n = block.element(e);
        linear.nodes.insert(linear.nodes.end(), n.begin(), n.begin() + count);
      }
    }
    out.emplace(id, std::move(corners));
  }
  return out;
}

void checkEdgeNodes(const Mesh& mesh, std::size_t maxProblems, std::vector<MeshProblem>& out) {
  std::vector<EntityId> entities;
  std::vector<EdgeRecord> records;
  for (const auto& [id, em] : mesh.entities()) {
    if (id.dim < 1) continue;
    entities.push_back(id);
    for (const ElementBlock& block : em.blocks)
      addRecords(block, entities.size() - 1, mesh, records);
  }
  std::sort(records.begin(), records.end());
  std::size_t reported = 0;
  for (std::size_t k = 0; k < records.size();) {
    std::size_t run = k + 1;
    for (; run < records.size() && records[run].key == records[k].key; ++run) {
      // Sorted, the records of one edge differ only where one group of equal ones ends.
      const EdgeRecord& previous = records[run - 1];
      if (records[run].inside == previous.inside || reported++ >= maxProblems) continue;
      const auto a = static_cast<NodeIndex>(records[k].key >> 32);
      const auto b = static_cast<NodeIndex>(records[k].key & 0xffffffffu);
      out.push_back({entities[records[run].entity],
                     "edge (" + std::to_string(a + 1) + ", " + std::to_string(b + 1) +
                         ") has the nodes " + nodeList(records[run].inside) +
                         " inside it in one element and " + nodeList(previous.inside) +
                         " in another"});
    }
    k = run;
  }
}

}  // namespace geomesh
