// elementsOfGroups, allElements, addChainGroup.
#include "mesh/homology/chain_groups.h"

#include <algorithm>
#include <set>

namespace geomesh {

namespace {

void appendElements(const EntityMesh& em, std::vector<ComplexElement>& out) {
  for (const ElementBlock& block : em.blocks) {
    const ElementFamily f = family(block.type);
    const int corners = vertexCount(f);
    for (std::size_t i = 0; i < block.size(); ++i) {
      ComplexElement e;
      e.family = f;
      const auto nodes = block.element(i);
      std::copy(nodes.begin(), nodes.begin() + corners, e.corners.begin());
      out.push_back(e);
    }
  }
}

// Node order of a volume element turned inside out.
std::vector<int> mirrored(ElementFamily f) {
  switch (f) {
    case ElementFamily::Tet:
      return {0, 2, 1, 3};
    case ElementFamily::Hex:
      return {0, 3, 2, 1, 4, 7, 6, 5};
    case ElementFamily::Prism:
      return {0, 2, 1, 3, 5, 4};
    default:
      return {0, 3, 2, 1, 4};
  }
}

// The cell's nodes, in its own orientation for a positive coefficient, reversed otherwise.
std::vector<NodeIndex> orientedNodes(const CellComplex& complex, CellId c, std::int64_t coef) {
  const auto nodes = complex.nodes(c);
  std::vector<NodeIndex> out(nodes.begin(), nodes.end());
  if (coef > 0 || out.size() == 1) return out;
  switch (dimension(complex.family(c))) {
    case 1:
      std::swap(out[0], out[1]);
      break;
    case 2:
      std::reverse(out.begin() + 1, out.end());
      break;
    default: {
      const std::vector<int> order = mirrored(complex.family(c));
      for (std::size_t k = 0; k < order.size(); ++k) out[k] = nodes[order[k]];
    }
  }
  return out;
}

int nextEntityTag(const Model& model, const Mesh& mesh) {
  int largest = 0;
  for (int dim = 0; dim <= 3; ++dim) largest = std::max(largest, model.maxTag(dim));
  for (const auto& [id, em] : mesh.entities()) largest = std::max(largest, id.tag);
  return largest + 1;
}

int nextPhysicalTag(const Model& model) {
  int largest = 0;
  for (const auto& [id, group] : model.physicalGroups()) largest = std::max(largest, id.tag);
  return largest + 1;
}

void addDiscreteEntity(Model& model, const Mesh& mesh, EntityId id, NodeIndex anyNode) {
  switch (id.dim) {
    case 0:
      model.addPoint({id.tag, mesh.node(anyNode), 0});
      break;
    case 1:
      model.addCurve({id.tag, 0, 0, nullptr});
      break;
    case 2:
      model.addSurface({id.tag, {}, nullptr, {}, {}});
      break;
    default:
      model.addVolume({id.tag, {}});
      break;
  }
}

}  // namespace

std::vector<ComplexElement> elementsOfGroups(const Model& model, const Mesh& mesh,
                                             std::span<const int> tags) {
  std::set<EntityId> entities;
  for (const auto& [id, group] : model.physicalGroups())
    if (std::find(tags.begin(), tags.end(), id.tag) != tags.end())
      for (int member : group.entities) entities.insert({id.dim, std::abs(member)});
  std::vector<ComplexElement> out;
  for (EntityId e : entities)
    if (const EntityMesh* em = mesh.find(e)) appendElements(*em, out);
  return out;
}

std::vector<ComplexElement> highestDimensionElements(const Mesh& mesh) {
  int top = 0;
  for (const auto& [id, em] : mesh.entities())
    if (em.elementCount() > 0) top = std::max(top, id.dim);
  std::vector<ComplexElement> out;
  for (const auto& [id, em] : mesh.entities())
    if (id.dim == top) appendElements(em, out);
  return out;
}

int addChainGroup(const CellComplex& complex, const Chain& chain, int dim, const std::string& name,
                  Model& model, Mesh& mesh) {
  const EntityId id{dim, nextEntityTag(model, mesh)};
  EntityMesh& em = mesh.entity(id);
  for (const auto& [cell, coef] : chain) {
    const std::vector<NodeIndex> nodes = orientedNodes(complex, cell, coef);
    ElementBlock& block = em.block(linearType(complex.family(cell)));
    block.nodes.insert(block.nodes.end(), nodes.begin(), nodes.end());
  }
  addDiscreteEntity(model, mesh, id, chain.empty() ? 0 : complex.nodes(chain.front().first)[0]);
  const int physical = nextPhysicalTag(model);
  model.addPhysicalGroup({dim, physical, name, {id.tag}});
  return physical;
}

}  // namespace geomesh
