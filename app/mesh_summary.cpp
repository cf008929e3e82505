// Element counts, measures, quality, validity of curved elements and physical groups of a
// mesh, and their printed form.
#include "app/mesh_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <sstream>

#include "kernel/extrusion_motion.h"
#include "mesh/core/quality.h"
#include "mesh/high_order/jacobian.h"

namespace geomesh {

namespace {

std::vector<Vec3> elementNodes(const Mesh& mesh, std::span<const NodeIndex> nodes) {
  std::vector<Vec3> out;
  out.reserve(nodes.size());
  for (NodeIndex n : nodes) out.push_back(mesh.node(n));
  return out;
}

// Curved elements are measured by quadrature over their own shape.
double blockMeasure(const Mesh& mesh, const ElementBlock& block) {
  double total = 0;
  for (std::size_t i = 0; i < block.size(); ++i)
    total += order(block.type) >= 2
                 ? elementMeasure(block.type, elementNodes(mesh, block.element(i)))
                 : elementMeasure(mesh, block.type, block.element(i));
  return total;
}

void addMeasures(const Mesh& mesh, MeshSummary& s) {
  for (const auto& [id, em] : mesh.entities()) {
    for (const ElementBlock& block : em.blocks) {
      s.elements[block.type] += block.size();
      const double total = blockMeasure(mesh, block);
      switch (dimension(block.type)) {
        case 1: s.length += total; break;
        case 2: s.area += total; break;
        case 3: s.volume += total; break;
        default: break;
      }
      if (family(block.type) == ElementFamily::Hex) s.hexahedraVolume += total;
    }
  }
}

// Interior and irregular vertices of the quadrangles (by their corners), when there are any:
// the edges of all the surface elements together; a vertex counts when all its elements are
// quadrangles and none of its edges belongs to one element only.
void addQuadStructure(const Mesh& mesh, MeshSummary& s) {
  bool quads = false;
  for (const auto& [type, n] : s.elements) quads = quads || family(type) == ElementFamily::Quad;
  if (!quads) return;
  std::vector<std::uint64_t> edges;
  std::vector<std::uint8_t> nearTriangle(mesh.nodeCount(), 0);
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& block : em.blocks) {
      if (dimension(block.type) != 2) continue;
      const auto corners = static_cast<std::size_t>(vertexCount(block.type));
      for (std::size_t i = 0; i < block.size(); ++i) {
        const auto nodes = block.element(i);
        for (std::size_t k = 0; k < corners; ++k) {
          if (corners != 4) nearTriangle[nodes[k]] = 1;
          const NodeIndex a = std::min(nodes[k], nodes[(k + 1) % corners]);
          const NodeIndex b = std::max(nodes[k], nodes[(k + 1) % corners]);
          edges.push_back(std::uint64_t{a} << 32 | b);
        }
      }
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint32_t> valence(mesh.nodeCount(), 0);
  std::vector<std::uint8_t> used(mesh.nodeCount(), 0), onBoundary(mesh.nodeCount(), 0);
  for (std::size_t i = 0, j; i < edges.size(); i = j) {
    for (j = i + 1; j < edges.size() && edges[j] == edges[i];) ++j;
    for (const auto n : {NodeIndex(edges[i] >> 32), NodeIndex(edges[i] & 0xffffffffu)}) {
      ++valence[n];
      used[n] = 1;
      if (j - i == 1) onBoundary[n] = 1;
    }
  }
  for (std::size_t n = 0; n < valence.size(); ++n) {
    if (!used[n] || onBoundary[n] || nearTriangle[n]) continue;
    ++s.interiorVertices;
    if (valence[n] != 4) ++s.irregularVertices;
  }
}

void addCurvedValidity(const Mesh& mesh, MeshSummary& s) {
  for (const auto& [type, n] : s.elements) s.highOrder = s.highOrder || order(type) >= 2;
  if (!s.highOrder) return;
  s.minScaledJacobian = 1;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& block : em.blocks) {
      if (dimension(block.type) == 0) continue;
      for (std::size_t i = 0; i < block.size(); ++i) {
        const double q = scaledJacobian(block.type, elementNodes(mesh, block.element(i)));
        s.minScaledJacobian = std::min(s.minScaledJacobian, q);
        if (q <= 0) ++s.invalidElements;
      }
    }
}

bool grownAlongNormals(const std::optional<ExtrusionRecord>& extrusion) {
  return extrusion && extrusion->motion &&
         extrusion->motion->kind == ExtrusionMotion::Kind::Normals;
}

// The first `count` elements of a block, or all of them (count = npos).
void addLayerQuality(const Mesh& mesh, const ElementBlock& block, std::size_t count,
                     MeshSummary& s, double& total) {
  count = std::min(count, block.size());
  for (std::size_t i = 0; i < count; ++i) {
    const double q = cornerScaledJacobian(block.type, elementNodes(mesh, block.element(i)));
    s.layerMinJacobian = s.layerElements == 0 ? q : std::min(s.layerMinJacobian, q);
    ++s.layerElements;
    total += q;
  }
}

// The layer elements of the highest dimension that has any.
void addLayers(const Model& model, const Mesh& mesh, MeshSummary& s) {
  double total = 0;
  for (int dim = 3; dim >= 2 && s.layerElements == 0; --dim)
    for (const auto& [id, em] : mesh.entities()) {
      if (id.dim != dim) continue;
      const ModelVolume* volume = dim == 3 ? model.volume(id.tag) : nullptr;
      const ModelSurface* surface = dim == 2 ? model.surface(id.tag) : nullptr;
      const bool grown = (volume && grownAlongNormals(volume->extrusion)) ||
                         (surface && grownAlongNormals(surface->extrusion));
      for (const ElementBlock& block : em.blocks) {
        if (dimension(block.type) != dim) continue;
        if (grown)
          addLayerQuality(mesh, block, block.size(), s, total);
        else if (em.layer && family(block.type) == ElementFamily::Triangle)
          addLayerQuality(mesh, block, em.layer->triangles, s, total);
        else if (em.layer && family(block.type) == ElementFamily::Quad)
          addLayerQuality(mesh, block, em.layer->quadrangles, s, total);
      }
    }
  if (s.layerElements > 0) s.layerMeanJacobian = total / static_cast<double>(s.layerElements);
}

void addGroups(const Model& model, const Mesh& mesh, MeshSummary& s) {
  for (const auto& [id, group] : model.physicalGroups()) {
    MeshSummary::Group g{group.dim, group.tag, group.name, 0};
    for (int tag : group.entities)
      if (const EntityMesh* em = mesh.find({group.dim, tag})) g.elements += em->elementCount();
    s.physicalGroups.push_back(g);
  }
  // Groups made per partition hold pieces of the partitions, not model entities.
  const MeshPartitions* partitions = mesh.partitions();
  if (!partitions) return;
  std::map<EntityId, const PartitionEntity*> pieces;
  for (const PartitionEntity& piece : partitions->entities) pieces[piece.id] = &piece;
  for (const PhysicalGroup& group : partitions->physicalGroups) {
    MeshSummary::Group g{group.dim, group.tag, group.name, 0};
    for (int tag : group.entities)
      if (const auto it = pieces.find({group.dim, tag}); it != pieces.end())
        for (const ElementBlock& b : it->second->blocks) g.elements += b.size();
    s.physicalGroups.push_back(g);
  }
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

MeshSummary summarizeMesh(const Model& model, const Mesh& mesh) {
  MeshSummary s;
  s.nodes = mesh.nodeCount();
  addMeasures(mesh, s);
  addCurvedValidity(mesh, s);
  addGroups(model, mesh, s);
  addLayers(model, mesh, s);
  addQuadStructure(mesh, s);
  // Quality of the highest-dimensional elements present.
  for (int dim = 3; dim >= 2; --dim) {
    QualityStats q = meshQuality(mesh, dim, QualityMeasure::Gamma);
    if (q.count == 0) continue;
    s.minQuality = q.min;
    s.meanQuality = q.mean;
    break;
  }
  return s;
}

std::string formatSummary(const MeshSummary& s) {
  std::ostringstream os;
  std::size_t total = 0;
  for (const auto& [type, n] : s.elements) total += n;
  os << plural(s.nodes, "node") << ", " << plural(total, "element");
  if (!s.elements.empty()) {
    os << " (";
    bool first = true;
    for (const auto& [type, n] : s.elements) {
      os << (first ? "" : ", ") << n << ' ' << elementName(type);
      first = false;
    }
    os << ")";
  }
  os.precision(6);
  if (s.volume > 0) os << "; volume " << s.volume;
  if (s.area > 0) os << "; area " << s.area;
  if (s.length > 0) os << "; length " << s.length;
  if (s.meanQuality > 0) {
    os.precision(4);
    os << "; quality (gamma) min " << s.minQuality << ", mean " << s.meanQuality;
  }
  return os.str();
}

std::string formatCurvedValidity(const MeshSummary& s) {
  if (!s.highOrder) return {};
  std::ostringstream os;
  os.precision(4);
  os << "curved elements: scaled Jacobian min " << s.minScaledJacobian << ", "
     << s.invalidElements << " invalid";
  return os.str();
}

std::string formatLayerQuality(const MeshSummary& s) {
  if (s.layerElements == 0) return {};
  std::ostringstream os;
  os.precision(4);
  os << "boundary layer: " << plural(s.layerElements, "element") << ", scaled Jacobian min "
     << s.layerMinJacobian << ", mean " << s.layerMeanJacobian;
  return os.str();
}

std::string formatQuadStructure(const MeshSummary& s) {
  bool quads = false;
  for (const auto& [type, n] : s.elements) quads = quads || family(type) == ElementFamily::Quad;
  if (!quads) return {};
  return "quadrangles: " + std::to_string(s.irregularVertices) + " of " +
         std::to_string(s.interiorVertices) +
         (s.interiorVertices == 1 ? " interior vertex" : " interior vertices") +
         " irregular (not 4 edges)";
}

std::string formatHexShare(const MeshSummary& s) {
  if (s.hexahedraVolume <= 0) return {};
  std::ostringstream os;
  os.precision(4);
  os << "hexahedra: " << 100 * s.hexahedraVolume / s.volume << "% of the volume";
  return os.str();
}

std::string describeModel(const Model& model) {
  return plural(model.points().size(), "point") + ", " + plural(model.curves().size(), "curve") +
         ", " + plural(model.surfaces().size(), "surface") + ", " +
         plural(model.volumes().size(), "volume") + ", " +
         plural(model.physicalGroups().size(), "physical group");
}

}  // namespace geomesh
