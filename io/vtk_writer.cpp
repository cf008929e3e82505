// Legacy VTK (ASCII): DATASET UNSTRUCTURED_GRID with POINTS, CELLS, CELL_TYPES and the entity
// tag of each cell as CELL_DATA. Linear elements and VTK's quadratic cells.
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/formats.h"
#include "io/msh_content.h"
#include "mesh/high_order/reference_element.h"

namespace geomesh {

namespace {

// A VTK cell: its type number, and where each of its nodes after the corners lies, as the
// corners (same numbering in VTK and MSH) whose centre it is: an edge's middle, a face's centre,
// the cell's centre. These are the node orders VTK documents for its quadratic cells.
struct VtkCell {
  ElementType type;
  int vtkType;
  std::vector<std::vector<int>> centres;
};

const std::vector<VtkCell>& vtkCells() {
  using C = std::vector<std::vector<int>>;
  const C hexEdges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                      {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  C hexAll = hexEdges;
  hexAll.insert(hexAll.end(), {{0, 4, 7, 3},
                               {1, 2, 6, 5},
                               {0, 1, 5, 4},
                               {3, 2, 6, 7},
                               {0, 1, 2, 3},
                               {4, 5, 6, 7},
                               {0, 1, 2, 3, 4, 5, 6, 7}});
  const C prismEdges = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
  C prismAll = prismEdges;
  prismAll.insert(prismAll.end(), {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
  static const std::vector<VtkCell> cells = {
      {ElementType::Point1, 1, {}},
      {ElementType::Line2, 3, {}},
      {ElementType::Triangle3, 5, {}},
      {ElementType::Quad4, 9, {}},
      {ElementType::Tet4, 10, {}},
      {ElementType::Hex8, 12, {}},
      {ElementType::Prism6, 13, {}},
      {ElementType::Pyramid5, 14, {}},
      {ElementType::Line3, 21, {{0, 1}}},
      {ElementType::Triangle6, 22, {{0, 1}, {1, 2}, {2, 0}}},
      {ElementType::Quad8, 23, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}},
      {ElementType::Quad9, 28, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 1, 2, 3}}},
      {ElementType::Tet10, 24, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}},
      {ElementType::Hex20, 25, hexEdges},
      {ElementType::Hex27, 29, hexAll},
      {ElementType::Prism15, 26, prismEdges},
      {ElementType::Prism18, 32, prismAll},
      {ElementType::Pyramid13, 27,
       {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}}},
  };
  return cells;
}

// The MSH node at the centre of `corners`, found by its reference coordinates.
int nodeAtCentre(const ReferenceElement& ref, const std::vector<int>& corners) {
  std::array<double, 3> centre{};
  for (int c : corners)
    for (int k = 0; k < 3; ++k) centre[k] += ref.xi[c][k] / static_cast<double>(corners.size());
  for (std::size_t n = 0; n < ref.xi.size(); ++n)
    if (std::abs(ref.xi[n][0] - centre[0]) + std::abs(ref.xi[n][1] - centre[1]) +
            std::abs(ref.xi[n][2] - centre[2]) <
        1e-12)
      return static_cast<int>(n);
  throw std::logic_error(std::string("no node of ") + elementName(ref.type) +
                         " at a corner centre");
}

// How an element type is written: VTK's type number and, for each VTK node, the index of the
// element's node that goes there.
struct VtkLayout {
  int vtkType = 0;
  std::vector<int> fromMsh;
};

std::map<ElementType, VtkLayout> buildLayouts() {
  std::map<ElementType, VtkLayout> layouts;
  for (const VtkCell& cell : vtkCells()) {
    VtkLayout& layout = layouts[cell.type];
    layout.vtkType = cell.vtkType;
    for (int c = 0; c < vertexCount(cell.type); ++c) layout.fromMsh.push_back(c);
    for (const std::vector<int>& corners : cell.centres)
      layout.fromMsh.push_back(nodeAtCentre(referenceElement(cell.type), corners));
  }
  return layouts;
}

// Throws std::invalid_argument for the types VTK's fixed cells cannot hold.
const VtkLayout& vtkLayout(ElementType type) {
  static const std::map<ElementType, VtkLayout> layouts = buildLayouts();
  const auto it = layouts.find(type);
  if (it != layouts.end()) return it->second;
  if (order(type) > 2)
    throw std::invalid_argument(std::string("VTK output of ") + elementName(type) +
                                " elements is not supported: vtk files hold elements up to "
                                "order 2");
  throw std::invalid_argument(std::string("VTK output of ") + elementName(type) +
                              " elements is not supported: VTK has no cell with these nodes");
}

void writeReal(std::ostream& out, double v) {
  char digits[32];
  out.write(digits, std::to_chars(digits, digits + sizeof digits, v, std::chars_format::general,
                                  16).ptr - digits);
}

// Saved nodes in the order of their tags: each node block's nodes follow the previous ones.
void writePoints(std::ostream& out, const Mesh& mesh, const MshContent& content) {
  out << "POINTS " << content.nodeCount << " double\n";
  for (const MshNodeBlock& block : content.nodeBlocks) {
    for (NodeIndex n : block.nodes) {
      const Vec3 p = mesh.node(n);
      writeReal(out, p.x);
      out << ' ';
      writeReal(out, p.y);
      out << ' ';
      writeReal(out, p.z);
      out << '\n';
    }
  }
}

void writeCells(std::ostream& out, const MshContent& content) {
  std::size_t size = 0;
  for (const MshElementBlock& b : content.elementBlocks)
    size += b.block->size() * (nodeCount(b.block->type) + 1);
  out << "CELLS " << content.elementCount << ' ' << size << '\n';
  for (const MshElementBlock& b : content.elementBlocks) {
    const VtkLayout& layout = vtkLayout(b.block->type);
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      const auto nodes = b.block->element(i);
      out << nodes.size();
      for (int k : layout.fromMsh) out << ' ' << content.nodeTag[nodes[k]] - 1;
      out << '\n';
    }
  }
}

void writeCellTypes(std::ostream& out, const MshContent& content) {
  out << "CELL_TYPES " << content.elementCount << '\n';
  for (const MshElementBlock& b : content.elementBlocks) {
    const int type = vtkLayout(b.block->type).vtkType;
    for (std::size_t i = 0; i < b.block->size(); ++i) out << type << '\n';
  }
}

void writeEntityTags(std::ostream& out, const MshContent& content) {
  out << "CELL_DATA " << content.elementCount << '\n'
      << "SCALARS CellEntityIds int 1\nLOOKUP_TABLE default\n";
  for (const MshElementBlock& b : content.elementBlocks)
    for (std::size_t i = 0; i < b.block->size(); ++i) out << b.entity.tag << '\n';
}

}  // namespace

// Named by the vtk row of io/formats.cpp. Saves what an MSH file would (the elements of
// physical groups only, when there are groups and Mesh.SaveAll is off); always ASCII.
void writeVtk(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const MshContent content = selectMshContent(model, mesh, options.saveAll);
  for (const MshElementBlock& b : content.elementBlocks) vtkLayout(b.block->type);
  out << "# vtk DataFile Version 2.0\ngeomesh mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  writePoints(out, mesh, content);
  writeCells(out, content);
  writeCellTypes(out, content);
  writeEntityTags(out, content);
}

}  // namespace geomesh
