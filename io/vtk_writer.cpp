// Legacy VTK (ASCII): DATASET UNSTRUCTURED_GRID with POINTS, CELLS, CELL_TYPES and the entity
// tag of each cell as CELL_DATA. Linear elements only.
#include <charconv>
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/formats.h"
#include "io/msh_content.h"

namespace geomesh {

namespace {

// VTK's cell type numbers; higher-order elements order their nodes differently and are
// refused.
int vtkCellType(ElementType type) {
  switch (type) {
    case ElementType::Point1: return 1;
    case ElementType::Line2: return 3;
    case ElementType::Triangle3: return 5;
    case ElementType::Quad4: return 9;
    case ElementType::Tet4: return 10;
    case ElementType::Hex8: return 12;
    case ElementType::Prism6: return 13;
    case ElementType::Pyramid5: return 14;
    default:
      throw std::invalid_argument(std::string("VTK output of ") + elementName(type) +
                                  " elements is not supported yet (linear elements only)");
  }
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
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      out << nodeCount(b.block->type);
      for (NodeIndex n : b.block->element(i)) out << ' ' << content.nodeTag[n] - 1;
      out << '\n';
    }
  }
}

void writeCellTypes(std::ostream& out, const MshContent& content) {
  out << "CELL_TYPES " << content.elementCount << '\n';
  for (const MshElementBlock& b : content.elementBlocks) {
    const int type = vtkCellType(b.block->type);
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
  for (const MshElementBlock& b : content.elementBlocks) vtkCellType(b.block->type);
  out << "# vtk DataFile Version 2.0\ngeomesh mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  writePoints(out, mesh, content);
  writeCells(out, content);
  writeCellTypes(out, content);
  writeEntityTags(out, content);
}

}  // namespace geomesh
