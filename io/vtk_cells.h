// The VTK cells of geomesh's element types, and the grid of cells both VTK writers (legacy and
// XML) save: one place for VTK's node orders, shared by the writers and the reader.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// How an element type is saved as a VTK cell: VTK's type number and, for each VTK node, the
// index of the element's node that goes there.
struct VtkLayout {
  ElementType type = ElementType::Point1;
  int vtkType = 0;
  std::vector<int> fromMsh;
};

// Throws std::invalid_argument naming the type (and the order above 2) for the types VTK's
// fixed cells cannot hold.
const VtkLayout& vtkLayout(ElementType type);

// How a VTK cell of `vtkType` with `nodes` nodes is read: the layouts above, plus VTK's cells
// that are other orderings of them (pixel, voxel, a polygon of 3 or 4 nodes). Null for a cell
// geomesh has no element for, or a node count that does not fit the type.
const VtkLayout* vtkLayoutForReading(int vtkType, std::size_t nodes);

// What a VTK file of a mesh holds: the saved nodes (as an MSH file saves them, in the order of
// their tags), and per cell its VTK type, its nodes (0-based, in VTK's order) and the tag of
// its entity.
struct VtkGrid {
  std::vector<NodeIndex> points;
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;  // where each cell's nodes end in `connectivity`
  std::vector<std::int32_t> entityTags;
};

// Throws std::invalid_argument, before a file is started, when an element cannot be saved.
VtkGrid buildVtkGrid(const Model& model, const Mesh& mesh, bool saveAll);

}  // namespace geomesh
