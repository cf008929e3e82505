// Plugin Skin: the boundary of a view's elements (faces of volumes, edges of surfaces, end
// points of lines) that belong to one element only, with their values; or (FromMesh = 1) the
// boundary of the session mesh's volumes (or surfaces), as a view of zeros.
#include <algorithm>
#include <array>
#include <map>
#include <tuple>
#include <vector>

#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

constexpr std::string_view kPlugin = "Skin";

// The facets of a shape, as corner numbers, oriented outwards for volumes.
std::vector<std::vector<int>> facets(ElementShape shape) {
  switch (shape) {
    case ElementShape::Point:
      return {};
    case ElementShape::Line:
      return {{0}, {1}};
    case ElementShape::Triangle:
      return {{0, 1}, {1, 2}, {2, 0}};
    case ElementShape::Quadrangle:
      return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    case ElementShape::Tetrahedron:
      return {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    case ElementShape::Hexahedron:
      return {{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3}, {1, 2, 6, 5}, {2, 3, 7, 6}, {4, 5, 6, 7}};
    case ElementShape::Prism:
      return {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}};
    case ElementShape::Pyramid:
      return {{0, 3, 2, 1}, {0, 1, 4}, {0, 4, 3}, {1, 2, 4}, {2, 3, 4}};
  }
  return {};
}

ElementShape facetShape(std::size_t corners) {
  return corners == 1   ? ElementShape::Point
         : corners == 2 ? ElementShape::Line
         : corners == 3 ? ElementShape::Triangle
                        : ElementShape::Quadrangle;
}

using Point = std::array<double, 3>;
using FacetKey = std::vector<Point>;  // the facet's corners, sorted

struct FacetUse {
  const ElementList* list;
  std::size_t element;
  std::size_t facet;
  int count;
};

// Every facet of the lists of dimension `dim`, with how many elements hold it.
std::map<FacetKey, FacetUse> countFacets(const View& view, int dim) {
  std::map<FacetKey, FacetUse> uses;
  for (const ElementList& list : view.lists) {
    if (list.size() == 0 || shapeDimension(list.shape) != dim) continue;
    const std::vector<std::vector<int>> shapeFacets = facets(list.shape);
    for (std::size_t e = 0; e < list.size(); ++e)
      for (std::size_t f = 0; f < shapeFacets.size(); ++f) {
        FacetKey key;
        for (int corner : shapeFacets[f]) {
          const Vec3 p = elementNode(list, e, corner);
          key.push_back({p.x, p.y, p.z});
        }
        std::sort(key.begin(), key.end());
        auto [it, inserted] = uses.try_emplace(key, FacetUse{&list, e, f, 0});
        ++it->second.count;
      }
  }
  return uses;
}

void appendFacet(const FacetUse& use, View& result) {
  const ElementList& list = *use.list;
  const std::vector<int> corners = facets(list.shape)[use.facet];
  ElementList& out = result.list(facetShape(corners.size()), list.kind);
  out.steps = list.steps;
  std::vector<Vec3> nodes;
  for (int corner : corners) nodes.push_back(elementNode(list, use.element, corner));
  std::vector<double> values;
  for (int s = 0; s < list.steps; ++s)
    for (int corner : corners)
      for (int c = 0; c < list.components(); ++c)
        values.push_back(list.value(use.element, s, corner, c));
  appendElement(out, nodes, values);
}

// A facet of the mesh: its corners as its first element gives them, and how many hold it.
struct MeshFacet {
  std::vector<NodeIndex> corners;
  std::size_t firstSeen;
  int count;
};

// Every facet of the mesh's elements of dimension `dim`, keyed by its sorted corners.
std::map<std::vector<NodeIndex>, MeshFacet> countMeshFacets(const Mesh& mesh, int dim) {
  std::map<std::vector<NodeIndex>, MeshFacet> uses;
  for (const auto& [id, entity] : mesh.entities()) {
    if (id.dim != dim) continue;
    for (const ElementBlock& block : entity.blocks) {
      const std::vector<std::vector<int>> shapeFacets =
          facets(ElementShape(static_cast<int>(family(block.type))));  // same order
      for (std::size_t i = 0; i < block.size(); ++i)
        for (const std::vector<int>& facet : shapeFacets) {
          std::vector<NodeIndex> corners;
          for (int corner : facet) corners.push_back(block.element(i)[std::size_t(corner)]);
          std::vector<NodeIndex> key = corners;
          std::sort(key.begin(), key.end());
          auto [it, inserted] = uses.try_emplace(key, MeshFacet{corners, uses.size(), 0});
          ++it->second.count;
        }
    }
  }
  return uses;
}

// The faces of the mesh's volumes held by one volume (or, without volumes, the edges of its
// surfaces held by one surface element), as a new view "Skin" of zeros.
void skinOfMesh(PluginContext& context) {
  const Mesh& mesh = context.mesh;
  const int dim = mesh.elementCount(3) > 0 ? 3 : mesh.elementCount(2) > 0 ? 2 : 0;
  if (dim == 0) fail(kPlugin, "FromMesh = 1: the mesh has no volume or surface element");
  const std::map<std::vector<NodeIndex>, MeshFacet> uses = countMeshFacets(mesh, dim);
  std::vector<const MeshFacet*> boundary;
  for (const auto& [key, use] : uses)
    if (use.count == 1) boundary.push_back(&use);
  std::sort(boundary.begin(), boundary.end(),
            [](const MeshFacet* a, const MeshFacet* b) { return a->firstSeen < b->firstSeen; });
  View result;
  for (const MeshFacet* facet : boundary) {
    std::vector<Vec3> nodes;
    for (NodeIndex n : facet->corners) nodes.push_back(mesh.node(n));
    appendElement(result.list(facetShape(nodes.size()), FieldKind::Scalar), nodes,
                  std::vector<double>(nodes.size(), 0.0));
  }
  context.views.add("Skin").lists = std::move(result.lists);
}

}  // namespace

void skin(const PluginOptions& options, PluginContext& context) {
  if (options.number("FromMesh", 0) != 0) return skinOfMesh(context);
  const std::size_t index = viewIndex(options, context, kPlugin);
  const View& view = context.views.at(index);
  int dim = 0;
  for (const ElementList& list : view.lists)
    if (list.size() > 0) dim = std::max(dim, shapeDimension(list.shape));
  if (dim == 0) fail(kPlugin, "view \"" + view.name + "\" has no line, surface or volume");
  // Facets in the order of their elements, so that the result does not depend on the map.
  std::vector<const FacetUse*> boundary;
  const std::map<FacetKey, FacetUse> uses = countFacets(view, dim);
  for (const auto& [key, use] : uses)
    if (use.count == 1) boundary.push_back(&use);
  std::sort(boundary.begin(), boundary.end(), [](const FacetUse* a, const FacetUse* b) {
    return std::tie(a->list, a->element, a->facet) < std::tie(b->list, b->element, b->facet);
  });
  View result;
  for (const FacetUse* use : boundary) appendFacet(*use, result);
  View& added = context.views.add(view.name + "_Skin");
  added.lists = std::move(result.lists);
  added.times = context.views.at(index).times;
}

}  // namespace geomesh::post::plugins
