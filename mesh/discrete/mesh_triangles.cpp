// meshTriangles and connectedParts.
#include "mesh/discrete/mesh_triangles.h"

#include <limits>

namespace geomesh {

namespace {

constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();

}  // namespace

MeshTriangles meshTriangles(const Mesh& mesh) {
  MeshTriangles result;
  std::vector<std::uint32_t> vertexOf(mesh.nodeCount(), kUnset);
  auto vertex = [&](NodeIndex n) {
    if (vertexOf[n] == kUnset) {
      vertexOf[n] = static_cast<std::uint32_t>(result.node.size());
      result.node.push_back(n);
      result.triangulation.points.push_back(mesh.node(n));
    }
    return vertexOf[n];
  };
  for (const auto& [id, em] : mesh.entities()) {
    for (const ElementBlock& block : em.blocks) {
      if (dimension(block.type) != 2) continue;
      const int corners = vertexCount(block.type);
      for (std::size_t e = 0; e < block.size(); ++e) {
        const auto nodes = block.element(e);
        for (int k = 1; k + 1 < corners; ++k)
          result.triangulation.triangles.push_back(
              {vertex(nodes[0]), vertex(nodes[static_cast<std::size_t>(k)]),
               vertex(nodes[static_cast<std::size_t>(k + 1)])});
      }
    }
  }
  return result;
}

std::vector<Triangulation> connectedParts(const Triangulation& t) {
  DisjointSets sets(t.points.size());
  for (const TriangleVertices& v : t.triangles) {
    sets.join(v[0], v[1]);
    sets.join(v[0], v[2]);
  }
  std::vector<Triangulation> parts;
  std::vector<std::uint32_t> partOf(t.points.size(), kUnset), local(t.points.size(), kUnset);
  for (const TriangleVertices& v : t.triangles) {
    std::uint32_t& part = partOf[sets.find(v[0])];
    if (part == kUnset) {
      part = static_cast<std::uint32_t>(parts.size());
      parts.emplace_back();
    }
    Triangulation& p = parts[part];
    TriangleVertices& out = p.triangles.emplace_back();
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t g = v[static_cast<std::size_t>(k)];
      if (local[g] == kUnset) {
        local[g] = static_cast<std::uint32_t>(p.points.size());
        p.points.push_back(t.points[g]);
      }
      out[static_cast<std::size_t>(k)] = local[g];
    }
  }
  return parts;
}

}  // namespace geomesh
