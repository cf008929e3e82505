// smoothMixedMesh (declared in recombine.h): Laplacian smoothing over triangles and quadrangles.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "mesh/quads/recombine.h"

namespace geomesh {
namespace {

struct ElementRef {
  std::uint32_t block, element;
};

// Neighbours (along element sides) and incident elements of each of the surface's own nodes.
struct NodeStar {
  static constexpr std::uint32_t kNotOwn = 0xffffffffu;
  std::vector<std::uint32_t> localOf;  // by global node: index in em.nodes, or kNotOwn
  std::vector<std::vector<NodeIndex>> neighbours;
  std::vector<std::vector<ElementRef>> elements;
};

NodeStar buildStars(const Mesh& mesh, const EntityMesh& em) {
  NodeStar star;
  star.localOf.assign(mesh.nodeCount(), NodeStar::kNotOwn);
  for (std::uint32_t k = 0; k < em.nodes.size(); ++k) star.localOf[em.nodes[k]] = k;
  star.neighbours.resize(em.nodes.size());
  star.elements.resize(em.nodes.size());
  for (std::uint32_t b = 0; b < em.blocks.size(); ++b) {
    const ElementBlock& block = em.blocks[b];
    if (block.type != ElementType::Triangle3 && block.type != ElementType::Quad4) continue;
    const int n = nodeCount(block.type);
    for (std::uint32_t e = 0; e < block.size(); ++e) {
      const auto nodes = block.element(e);
      for (int k = 0; k < n; ++k) {
        const std::uint32_t local = star.localOf[nodes[k]];
        if (local == NodeStar::kNotOwn) continue;
        star.elements[local].push_back({b, e});
        for (NodeIndex other : {nodes[(k + 1) % n], nodes[(k + n - 1) % n]}) {
          std::vector<NodeIndex>& list = star.neighbours[local];
          if (std::find(list.begin(), list.end(), other) == list.end()) list.push_back(other);
        }
      }
    }
  }
  return star;
}

bool elementValid(const Mesh& mesh, const ElementBlock& block, std::uint32_t e, Vec3 normal) {
  const auto n = block.element(e);
  if (block.type == ElementType::Triangle3) {
    const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]);
    const Vec3 area = cross(b - a, c - a);
    return dot(area, normal) > 1e-3 * norm(area) * norm(normal);
  }
  return quadAngleQuality(mesh.node(n[0]), mesh.node(n[1]), mesh.node(n[2]), mesh.node(n[3]),
                          normal) > 0.05;
}

bool starValid(const Mesh& mesh, const EntityMesh& em, const std::vector<ElementRef>& refs,
               Vec3 normal) {
  for (const ElementRef& r : refs)
    if (!elementValid(mesh, em.blocks[r.block], r.element, normal)) return false;
  return true;
}

}  // namespace

void smoothMixedMesh(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em, int passes) {
  const NodeStar star = buildStars(mesh, em);
  const bool haveParameters = em.parametric.size() == 2 * em.nodes.size();
  for (int pass = 0; pass < passes; ++pass)
    for (std::uint32_t k = 0; k < em.nodes.size(); ++k) {
      const std::vector<NodeIndex>& around = star.neighbours[k];
      if (around.empty()) continue;
      Vec3 mean{0, 0, 0};
      for (NodeIndex n : around) mean = mean + mesh.node(n);
      mean = mean / static_cast<double>(around.size());
      const Vec2 uv = g.project(mean);
      const SurfaceDerivatives d = g.firstDerivatives(uv);
      const Vec3 normal = cross(d.du, d.dv);
      const NodeIndex node = em.nodes[k];
      const Vec3 old = mesh.node(node);
      mesh.setNode(node, g.point(uv));
      if (!starValid(mesh, em, star.elements[k], normal)) {
        mesh.setNode(node, old);
        continue;
      }
      if (haveParameters) em.parametric[2 * k] = uv.u, em.parametric[2 * k + 1] = uv.v;
    }
}

}  // namespace geomesh
