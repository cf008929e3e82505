// removeTwoQuadNodes and removeDiamonds (declared in recombine.h): topological clean-up of a
// recombined surface, each pass removing nodes where too few quadrangles meet.
#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mesh/quads/recombine.h"

namespace geomesh {
namespace {

using Quad = std::array<NodeIndex, 4>;

// The surface's quadrangles, and for every node the elements around it: quadrangles by
// index, triangles only counted (they block a change around their nodes).
struct QuadStar {
  std::vector<Quad> quads;
  std::unordered_map<NodeIndex, std::vector<std::uint32_t>> quadsAround;
  std::unordered_map<NodeIndex, int> trianglesAround;

  explicit QuadStar(const EntityMesh& em) {
    if (const ElementBlock* block = em.findBlock(ElementType::Quad4))
      for (std::size_t e = 0; e < block->size(); ++e) {
        const auto n = block->element(e);
        const auto index = static_cast<std::uint32_t>(quads.size());
        quads.push_back({n[0], n[1], n[2], n[3]});
        for (NodeIndex x : n) quadsAround[x].push_back(index);
      }
    if (const ElementBlock* block = em.findBlock(ElementType::Triangle3))
      for (NodeIndex x : block->nodes) ++trianglesAround[x];
  }
  // The quadrangles around node x when only quadrangles hold it, else empty.
  std::vector<std::uint32_t> onlyQuadsAround(NodeIndex x) const {
    if (trianglesAround.contains(x)) return {};
    const auto it = quadsAround.find(x);
    return it == quadsAround.end() ? std::vector<std::uint32_t>{} : it->second;
  }
  int elementsAround(NodeIndex x) const {
    const auto q = quadsAround.find(x);
    const auto t = trianglesAround.find(x);
    return (q == quadsAround.end() ? 0 : static_cast<int>(q->second.size())) +
           (t == trianglesAround.end() ? 0 : t->second);
  }
};

// The quadrangle's corners from node x on, in its turning order.
Quad rotatedTo(const Quad& q, NodeIndex x) {
  const auto at = static_cast<std::size_t>(std::find(q.begin(), q.end(), x) - q.begin());
  return {q[at], q[(at + 1) % 4], q[(at + 2) % 4], q[(at + 3) % 4]};
}

Vec3 areaVector(const Mesh& mesh, const Quad& q) {
  return cross(mesh.node(q[2]) - mesh.node(q[0]), mesh.node(q[3]) - mesh.node(q[1]));
}

bool convexAlong(const Mesh& mesh, const Quad& q, Vec3 up) {
  if (q[0] == q[2] || q[1] == q[3]) return false;
  return quadAngleQuality(mesh.node(q[0]), mesh.node(q[1]), mesh.node(q[2]), mesh.node(q[3]), up) >
         kMinQuadQuality;
}

// Writes the quadrangles back (those flagged gone left out) and drops the removed nodes from
// the surface's own.
void store(EntityMesh& em, const std::vector<Quad>& quads, const std::vector<std::uint8_t>& gone,
           const std::unordered_set<NodeIndex>& removed) {
  ElementBlock& block = em.block(ElementType::Quad4);
  block.nodes.clear();
  for (std::size_t k = 0; k < quads.size(); ++k)
    if (!gone[k]) block.nodes.insert(block.nodes.end(), quads[k].begin(), quads[k].end());
  dropOwnNodes(em, removed);
}

}  // namespace

std::size_t removeTwoQuadNodes(const Mesh& mesh, EntityMesh& em) {
  QuadStar star(em);
  std::vector<std::uint8_t> gone(star.quads.size(), 0), touched(star.quads.size(), 0);
  std::unordered_set<NodeIndex> removed;
  for (NodeIndex x : em.nodes) {
    const std::vector<std::uint32_t> around = star.onlyQuadsAround(x);
    if (around.size() != 2 || touched[around[0]] || touched[around[1]]) continue;
    // (x p y q) and (x q z p): the two share both sides at x; (p y q z) remains.
    const Quad first = rotatedTo(star.quads[around[0]], x);
    const Quad second = rotatedTo(star.quads[around[1]], x);
    if (second[1] != first[3] || second[3] != first[1]) continue;
    const Quad merged{first[1], first[2], first[3], second[2]};
    const Vec3 up = areaVector(mesh, first) + areaVector(mesh, second);
    if (first[2] == second[2] || !convexAlong(mesh, merged, up)) continue;
    star.quads[around[0]] = merged;
    gone[around[1]] = 1;
    touched[around[0]] = touched[around[1]] = 1;
    removed.insert(x);
  }
  if (!removed.empty()) store(em, star.quads, gone, removed);
  return removed.size();
}

std::size_t removeDiamonds(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em) {
  QuadStar star(em);
  std::unordered_map<NodeIndex, std::size_t> ownIndex;
  for (std::size_t k = 0; k < em.nodes.size(); ++k) ownIndex[em.nodes[k]] = k;
  const bool withParameters = em.parametric.size() == 2 * em.nodes.size();
  std::vector<std::uint8_t> gone(star.quads.size(), 0), touched(star.quads.size(), 0);
  std::unordered_set<NodeIndex> removed;
  auto anyTouched = [&](const std::vector<std::uint32_t>& quads) {
    return std::any_of(quads.begin(), quads.end(), [&](std::uint32_t q) { return touched[q]; });
  };
  for (std::uint32_t d = 0; d < star.quads.size(); ++d) {
    for (int diagonal = 0; diagonal < 2 && !touched[d]; ++diagonal) {
      const Quad q = rotatedTo(star.quads[d], star.quads[d][diagonal]);
      const NodeIndex keep = q[0], merged = q[2];
      if (!ownIndex.contains(keep) || !ownIndex.contains(merged)) continue;
      const std::vector<std::uint32_t> atKeep = star.onlyQuadsAround(keep);
      const std::vector<std::uint32_t> atMerged = star.onlyQuadsAround(merged);
      if (atKeep.size() != 3 || atMerged.size() != 3 || anyTouched(atKeep) || anyTouched(atMerged))
        continue;
      // The other two corners lose the diamond: one of the surface's own left with two
      // elements would need a corner of at least 180 degrees.
      auto enoughLeft = [&](NodeIndex x) {
        return star.elementsAround(x) >= (ownIndex.contains(x) ? 4 : 2);
      };
      if (!enoughLeft(q[1]) || !enoughLeft(q[3])) continue;
      // The four quadrangles left around the merged node, with their area vectors before.
      std::vector<std::pair<std::uint32_t, Vec3>> changed;
      for (const std::vector<std::uint32_t>* list : {&atKeep, &atMerged})
        for (std::uint32_t k : *list)
          if (k != d) changed.push_back({k, areaVector(mesh, star.quads[k])});
      const Vec3 oldKeep = mesh.node(keep);
      const Vec2 uv = g.project(0.5 * (oldKeep + mesh.node(merged)));
      mesh.setNode(keep, g.point(uv));
      bool valid = true;
      for (const auto& [k, up] : changed) {
        Quad after = star.quads[k];
        std::replace(after.begin(), after.end(), merged, keep);
        valid = valid && convexAlong(mesh, after, up);
      }
      if (!valid) {
        mesh.setNode(keep, oldKeep);
        continue;
      }
      for (const auto& [k, up] : changed) {
        std::replace(star.quads[k].begin(), star.quads[k].end(), merged, keep);
        touched[k] = 1;
      }
      touched[d] = gone[d] = 1;
      removed.insert(merged);
      if (withParameters) {
        const std::size_t at = ownIndex.at(keep);
        em.parametric[2 * at] = uv.u, em.parametric[2 * at + 1] = uv.v;
      }
    }
  }
  if (!removed.empty()) store(em, star.quads, gone, removed);
  return removed.size();
}

}  // namespace geomesh
