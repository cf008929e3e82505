// SU2 native meshes (.su2): the elements of the mesh's top dimension, the nodes they use, and
// one marker per physical group of the dimension below with that group's elements.
#include <algorithm>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/formats.h"
#include "io/msh_content.h"
#include "io/node_order.h"
#include "io/physical_sets.h"
#include "io/real_text.h"

namespace geomesh {

namespace {

// SU2 numbers its element types as VTK does; it holds first-order elements only, with the
// corners in MSH order.
int su2Type(ElementType type) {
  switch (type) {
    case ElementType::Line2:
      return 3;
    case ElementType::Triangle3:
      return 5;
    case ElementType::Quad4:
      return 9;
    case ElementType::Tet4:
      return 10;
    case ElementType::Hex8:
      return 12;
    case ElementType::Prism6:
      return 13;
    case ElementType::Pyramid5:
      return 14;
    default:
      break;
  }
  refuseElementType("SU2", type,
                    order(type) > 1 ? "SU2 files hold first-order elements only"
                                    : "SU2 has no element type for them");
}

struct Su2Marker {
  std::string name;
  std::vector<std::size_t> blocks;  // in content.elementBlocks
};

// What an SU2 file holds, chosen and checked before anything is written.
struct Su2Content {
  int dim = 0;
  std::vector<std::size_t> cells;  // blocks of the top dimension
  std::vector<Su2Marker> markers;
  std::vector<NodeIndex> points;         // the nodes used, in the content's order
  std::vector<std::int64_t> pointIndex;  // per mesh node: its 0-based index, -1 if unused
};

// The points: the nodes of the written elements, numbered from 0 in the content's order.
void numberPoints(Su2Content& su2, const Mesh& mesh, const MshContent& content) {
  su2.pointIndex.assign(mesh.nodeCount(), -1);
  auto use = [&](std::size_t block) {
    su2Type(content.elementBlocks[block].block->type);
    for (NodeIndex n : content.elementBlocks[block].block->nodes) su2.pointIndex[n] = 0;
  };
  for (std::size_t i : su2.cells) use(i);
  for (const Su2Marker& marker : su2.markers)
    for (std::size_t i : marker.blocks) use(i);
  for (const MshNodeBlock& block : content.nodeBlocks)
    for (NodeIndex n : block.nodes)
      if (su2.pointIndex[n] == 0) su2.points.push_back(n);
  for (std::size_t i = 0; i < su2.points.size(); ++i)
    su2.pointIndex[su2.points[i]] = static_cast<std::int64_t>(i);
  if (su2.dim == 2)
    for (NodeIndex n : su2.points)
      if (mesh.node(n).z != 0)
        throw std::invalid_argument("SU2 meshes of dimension 2 lie in the plane z = 0");
}

Su2Content selectSu2Content(const Model& model, const Mesh& mesh, const MshContent& content) {
  Su2Content su2;
  for (const MshElementBlock& b : content.elementBlocks)
    su2.dim = std::max(su2.dim, dimension(b.block->type));
  if (su2.dim < 2)
    throw std::invalid_argument(
        "SU2 files hold meshes of dimension 2 or 3: no element of "
        "dimension 2 or 3 is saved");
  for (std::size_t i = 0; i < content.elementBlocks.size(); ++i)
    if (dimension(content.elementBlocks[i].block->type) == su2.dim) su2.cells.push_back(i);
  for (const auto& [id, group] : model.physicalGroups())
    if (group.dim == su2.dim - 1)
      su2.markers.push_back({physicalGroupName(group), groupBlocks(content, group)});
  numberPoints(su2, mesh, content);
  return su2;
}

// Each element: its type, its nodes and, in the element list, its index.
void writeElements(std::ostream& out, const MshContent& content, const Su2Content& su2,
                   const std::vector<std::size_t>& blocks, bool numbered) {
  std::size_t index = 0;
  for (std::size_t i : blocks) {
    const ElementBlock& block = *content.elementBlocks[i].block;
    const int type = su2Type(block.type);
    for (std::size_t e = 0; e < block.size(); ++e) {
      out << type;
      for (NodeIndex n : block.element(e)) out << ' ' << su2.pointIndex[n];
      if (numbered) out << ' ' << index++;
      out << '\n';
    }
  }
}

std::size_t elementCount(const MshContent& content, const std::vector<std::size_t>& blocks) {
  std::size_t count = 0;
  for (std::size_t i : blocks) count += content.elementBlocks[i].block->size();
  return count;
}

void writePoints(std::ostream& out, const Mesh& mesh, const Su2Content& su2) {
  out << "NPOIN= " << su2.points.size() << '\n';
  for (std::size_t i = 0; i < su2.points.size(); ++i) {
    const Vec3 p = mesh.node(su2.points[i]);
    writeShortestReal(out, p.x);
    out << ' ';
    writeShortestReal(out, p.y);
    if (su2.dim == 3) {
      out << ' ';
      writeShortestReal(out, p.z);
    }
    out << ' ' << i << '\n';
  }
}

}  // namespace

// Named by the su2 row of io/formats.cpp. Saves the elements an MSH file would, of the top
// dimension and in the markers; the other ones (lower-dimensional elements outside the
// markers) are left out.
void writeSu2(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const MshContent content = selectMshContent(model, mesh, options.saveAll);
  const Su2Content su2 = selectSu2Content(model, mesh, content);
  out << "NDIME= " << su2.dim << '\n';
  out << "NELEM= " << elementCount(content, su2.cells) << '\n';
  writeElements(out, content, su2, su2.cells, true);
  writePoints(out, mesh, su2);
  out << "NMARK= " << su2.markers.size() << '\n';
  for (const Su2Marker& marker : su2.markers) {
    out << "MARKER_TAG= " << marker.name << '\n';
    out << "MARKER_ELEMS= " << elementCount(content, marker.blocks) << '\n';
    writeElements(out, content, su2, marker.blocks, false);
  }
}

}  // namespace geomesh
