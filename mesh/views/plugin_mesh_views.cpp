// Plugins that make views on the session's mesh: ElementSize (each element's equivalent
// size) and NewView (nodal data, every value the same).
#include <algorithm>
#include <string>
#include <vector>

#include "mesh/core/quality.h"
#include "stdlib/clamped_integer.h"
#include "mesh/views/element_size.h"
#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

int highestDimension(const Mesh& mesh) {
  for (int d = 3; d > 0; --d)
    if (mesh.elementCount(d) > 0) return d;
  return 0;
}

// Calls f(shape, corner coordinates, type, nodes) for each element of dimension `dim`.
template <typename F>
void forEachMeshElement(const Mesh& mesh, int dim, F&& f) {
  std::vector<Vec3> corners;
  for (const auto& [id, entity] : mesh.entities()) {
    if (id.dim != dim) continue;
    for (const ElementBlock& block : entity.blocks) {
      const ElementShape shape = shapeOfFamily(elementInfo(block.type).family);
      for (std::size_t i = 0; i < block.size(); ++i) {
        const std::span<const NodeIndex> nodes = block.element(i);
        corners.clear();
        for (int k = 0; k < cornerCount(shape); ++k)
          corners.push_back(mesh.node(nodes[std::size_t(k)]));
        f(shape, corners, block.type, nodes);
      }
    }
  }
}

// Sizes of a view's elements of dimension `dim` (measures of their simplex split).
void viewElementSizes(const View& source, int dim, View& result) {
  for (const ElementList& list : source.lists) {
    if (list.size() == 0 || shapeDimension(list.shape) != dim) continue;
    ElementList& out = result.list(list.shape, FieldKind::Scalar);
    const int corners = cornerCount(list.shape);
    for (std::size_t e = 0; e < list.size(); ++e) {
      std::vector<Vec3> nodes;
      for (int k = 0; k < corners; ++k) nodes.push_back(elementNode(list, e, k));
      Mesh scratch;  // the element alone, to measure it as the mesh's elements are
      std::vector<NodeIndex> indices;
      for (const Vec3& p : nodes) indices.push_back(scratch.addNode(p));
      const ElementType type = list.shape == ElementShape::Line          ? ElementType::Line2
                               : list.shape == ElementShape::Triangle    ? ElementType::Triangle3
                               : list.shape == ElementShape::Quadrangle  ? ElementType::Quad4
                               : list.shape == ElementShape::Tetrahedron ? ElementType::Tet4
                               : list.shape == ElementShape::Hexahedron  ? ElementType::Hex8
                               : list.shape == ElementShape::Prism       ? ElementType::Prism6
                                                                         : ElementType::Pyramid5;
      const double size =
          equivalentElementSize(familyOfShape(list.shape), elementMeasure(scratch, type, indices));
      appendElement(out, nodes, std::vector<double>(std::size_t(corners), size));
    }
  }
}

}  // namespace

void elementSize(const PluginOptions& options, PluginContext& context) {
  constexpr std::string_view plugin = "ElementSize";
  const double dimension = options.number("Dimension", -1);
  if (dimension > 3 || (dimension >= 0 && dimension < 1))
    fail(plugin, optionText("Dimension", dimension) + ": not 1, 2, 3 or -1");
  View result;
  if (options.number("View", -1) >= 0) {
    const View& source = context.views.at(viewIndex(options, context, plugin));
    int dim = clampedInteger<int>(dimension);
    if (dim < 0)
      for (const ElementList& list : source.lists)
        if (list.size() > 0) dim = std::max(dim, shapeDimension(list.shape));
    viewElementSizes(source, dim, result);
  } else {
    const int dim = dimension < 0 ? highestDimension(context.mesh) : clampedInteger<int>(dimension);
    if (dim == 0 || context.mesh.elementCount(dim) == 0)
      fail(plugin, "the mesh has no element of dimension " + std::to_string(dim));
    forEachMeshElement(context.mesh, dim,
                       [&](ElementShape shape, const std::vector<Vec3>& corners, ElementType type,
                           std::span<const NodeIndex> nodes) {
                         const double size = equivalentElementSize(
                             familyOfShape(shape), elementMeasure(context.mesh, type, nodes));
                         appendElement(result.list(shape, FieldKind::Scalar), corners,
                                       std::vector<double>(corners.size(), size));
                       });
  }
  context.views.add("ElementSize").lists = std::move(result.lists);
}

void newView(const PluginOptions& options, PluginContext& context) {
  constexpr std::string_view plugin = "NewView";
  const double components = options.number("NumComp", 1);
  if (components != 1 && components != 3 && components != 9)
    fail(plugin, optionText("NumComp", components) + ": not 1, 3 or 9");
  const double value = options.number("Value", 0);
  const int dim = highestDimension(context.mesh);
  if (dim == 0 || context.mesh.nodeCount() == 0) fail(plugin, "there is no mesh");
  const FieldKind kind = components == 1   ? FieldKind::Scalar
                         : components == 3 ? FieldKind::Vector
                                           : FieldKind::Tensor;
  View& view = context.views.add("New view");
  forEachMeshElement(context.mesh, dim,
                     [&](ElementShape shape, const std::vector<Vec3>& corners, ElementType,
                         std::span<const NodeIndex>) {
                       appendElement(
                           view.list(shape, kind), corners,
                           std::vector<double>(corners.size() * std::size_t(components), value));
                     });
  MeshData data;
  data.kind = MeshData::Kind::Node;
  data.components = int(components);
  MeshData::Step& step = data.steps.emplace_back();
  for (std::size_t i = 0; i < context.mesh.nodeCount(); ++i) step.tags.push_back(i + 1);
  step.values.assign(context.mesh.nodeCount() * std::size_t(components), value);
  view.meshData = std::move(data);
}

}  // namespace geomesh::post::plugins
