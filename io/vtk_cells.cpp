// VTK's cell types and node orders for geomesh's element types, and the grid the writers save.
#include "io/vtk_cells.h"

#include <map>
#include <stdexcept>
#include <string>

#include "io/msh_content.h"
#include "io/node_order.h"

namespace geomesh {

namespace {

// A VTK cell: its type number, and where each of its nodes after the corners lies (corners
// are numbered alike in VTK and MSH). These are the node orders VTK documents for its quadratic
// cells.
struct VtkCell {
  ElementType type;
  int vtkType;
  NodePlaces centres;
};

std::vector<VtkCell> vtkCells() {
  NodePlaces hexAll = hexEdgesBottomTopVertical();
  hexAll.insert(hexAll.end(), {{0, 4, 7, 3},
                               {1, 2, 6, 5},
                               {0, 1, 5, 4},
                               {3, 2, 6, 7},
                               {0, 1, 2, 3},
                               {4, 5, 6, 7},
                               {0, 1, 2, 3, 4, 5, 6, 7}});
  NodePlaces prismAll = prismEdgesBottomTopVertical();
  prismAll.insert(prismAll.end(), {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
  NodePlaces quad9 = quadEdges();
  quad9.push_back({0, 1, 2, 3});
  return {
      {ElementType::Point1, 1, {}},
      {ElementType::Line2, 3, {}},
      {ElementType::Triangle3, 5, {}},
      {ElementType::Quad4, 9, {}},
      {ElementType::Tet4, 10, {}},
      {ElementType::Hex8, 12, {}},
      {ElementType::Prism6, 13, {}},
      {ElementType::Pyramid5, 14, {}},
      {ElementType::Line3, 21, {{0, 1}}},
      {ElementType::Triangle6, 22, triangleEdges()},
      {ElementType::Quad8, 23, quadEdges()},
      {ElementType::Quad9, 28, quad9},
      {ElementType::Tet10, 24, tetEdges()},
      {ElementType::Hex20, 25, hexEdgesBottomTopVertical()},
      {ElementType::Hex27, 29, hexAll},
      {ElementType::Prism15, 26, prismEdgesBottomTopVertical()},
      {ElementType::Prism18, 32, prismAll},
      {ElementType::Pyramid13, 27, pyramidEdges()},
  };
}

std::map<ElementType, VtkLayout> buildLayouts() {
  std::map<ElementType, VtkLayout> layouts;
  for (const VtkCell& cell : vtkCells())
    layouts[cell.type] = {cell.type, cell.vtkType,
                          mshNodesAt(cell.type, cornersThen(cell.type, cell.centres))};
  return layouts;
}

const std::map<ElementType, VtkLayout>& layouts() {
  static const std::map<ElementType, VtkLayout> all = buildLayouts();
  return all;
}

// VTK cells read as another ordering of a layout: the pixel and the voxel, whose corners go
// row by row instead of around.
const std::map<int, VtkLayout>& orderingsForReading() {
  static const std::map<int, VtkLayout> all = {
      {8, {ElementType::Quad4, 8, {0, 1, 3, 2}}},
      {11, {ElementType::Hex8, 11, {0, 1, 3, 2, 4, 5, 7, 6}}},
  };
  return all;
}

}  // namespace

const VtkLayout& vtkLayout(ElementType type) {
  const auto it = layouts().find(type);
  if (it != layouts().end()) return it->second;
  if (order(type) > 2)
    throw std::invalid_argument(std::string("VTK output of ") + elementName(type) +
                                " elements is not supported: vtk files hold elements up to "
                                "order 2");
  throw std::invalid_argument(std::string("VTK output of ") + elementName(type) +
                              " elements is not supported: VTK has no cell with these nodes");
}

const VtkLayout* vtkLayoutForReading(int vtkType, std::size_t nodes) {
  constexpr int kPolygon = 7;
  const VtkLayout* found = nullptr;
  if (vtkType == kPolygon && (nodes == 3 || nodes == 4)) {
    found = &vtkLayout(nodes == 3 ? ElementType::Triangle3 : ElementType::Quad4);
  } else if (const auto it = orderingsForReading().find(vtkType);
             it != orderingsForReading().end()) {
    found = &it->second;
  } else {
    for (const auto& [type, layout] : layouts())
      if (layout.vtkType == vtkType) found = &layout;
  }
  return found && found->fromMsh.size() == nodes ? found : nullptr;
}

VtkGrid buildVtkGrid(const Model& model, const Mesh& mesh, bool saveAll) {
  const MshContent content = selectMshContent(model, mesh, saveAll);
  for (const MshElementBlock& b : content.elementBlocks) vtkLayout(b.block->type);
  VtkGrid grid;
  grid.points.reserve(content.nodeCount);
  for (const MshNodeBlock& block : content.nodeBlocks)
    grid.points.insert(grid.points.end(), block.nodes.begin(), block.nodes.end());
  grid.types.reserve(content.elementCount);
  grid.offsets.reserve(content.elementCount);
  grid.entityTags.reserve(content.elementCount);
  for (const MshElementBlock& b : content.elementBlocks) {
    const VtkLayout& layout = vtkLayout(b.block->type);
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      const auto nodes = b.block->element(i);
      for (int k : layout.fromMsh)
        grid.connectivity.push_back(static_cast<std::int64_t>(content.nodeTag[nodes[k]]) - 1);
      grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
      grid.types.push_back(static_cast<std::uint8_t>(layout.vtkType));
      grid.entityTags.push_back(b.entity.tag);
    }
  }
  return grid;
}

}  // namespace geomesh
