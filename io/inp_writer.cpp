// Abaqus input files (.inp): *NODE, one *ELEMENT block per entity and element type, then per
// physical group an *ELSET and/or *NSET as Mesh.SaveGroupsOfElements/Nodes select.
#include <cctype>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "io/formats.h"
#include "io/msh_content.h"
#include "io/node_order.h"
#include "io/physical_sets.h"
#include "io/real_text.h"

namespace geomesh {

namespace {

// An Abaqus element type: its name and, for each node it lists, the index (in MSH order) of the
// element's node that goes there.
struct InpElement {
  ElementType type;
  const char* name;
  std::vector<int> fromMsh;
};

// Trusses for lines, plane stress elements for triangles and quadrangles, continuum solids
// for volumes. Abaqus numbers mid-edge nodes edge by edge: the bottom face's, the top face's,
// then the vertical edges'.
const std::vector<InpElement>& inpElements() {
  using T = ElementType;
  auto layout = [](ElementType type, const NodePlaces& centres) {
    return mshNodesAt(type, cornersThen(type, centres));
  };
  static const std::vector<InpElement> elements = {
      {T::Line2, "T3D2", layout(T::Line2, {})},
      {T::Line3, "T3D3", layout(T::Line3, {{0, 1}})},
      {T::Triangle3, "CPS3", layout(T::Triangle3, {})},
      {T::Triangle6, "CPS6", layout(T::Triangle6, triangleEdges())},
      {T::Quad4, "CPS4", layout(T::Quad4, {})},
      {T::Quad8, "CPS8", layout(T::Quad8, quadEdges())},
      {T::Tet4, "C3D4", layout(T::Tet4, {})},
      {T::Tet10, "C3D10", layout(T::Tet10, tetEdges())},
      {T::Prism6, "C3D6", layout(T::Prism6, {})},
      {T::Prism15, "C3D15", layout(T::Prism15, prismEdgesBottomTopVertical())},
      {T::Hex8, "C3D8", layout(T::Hex8, {})},
      {T::Hex20, "C3D20", layout(T::Hex20, hexEdgesBottomTopVertical())},
  };
  return elements;
}

// Point elements are not written: their nodes are.
const InpElement* inpElementOf(ElementType type) {
  if (type == ElementType::Point1) return nullptr;
  for (const InpElement& e : inpElements())
    if (e.type == type) return &e;
  if (family(type) == ElementFamily::Pyramid)
    refuseElementType("Abaqus", type, "Abaqus has no pyramid elements");
  refuseElementType("Abaqus", type,
                    order(type) > 2 ? "Abaqus elements are at most of order 2"
                                    : "Abaqus has no element with these nodes");
}

// A set name as Abaqus reads it: quoted when it is not a plain word.
std::string setName(const std::string& name) {
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return '"' + name + '"';
  return name;
}

std::string entityName(EntityId e) {
  static constexpr const char* kWords[] = {"Point", "Line", "Surface", "Volume"};
  return kWords[e.dim] + std::to_string(e.tag);
}

// Comma-separated values, at most 16 to a data line (Abaqus's limit); a line that goes on
// ends with a comma.
template <class Values>
void writeDataLines(std::ostream& out, const Values& values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    out << values[i];
    const bool last = i + 1 == values.size();
    out << (last ? "\n" : i % 16 == 15 ? ",\n" : ", ");
  }
}

void writeNodes(std::ostream& out, const Mesh& mesh, const MshContent& content) {
  out << "*NODE\n";
  for (const MshNodeBlock& block : content.nodeBlocks)
    for (NodeIndex n : block.nodes) {
      const Vec3 p = mesh.node(n);
      out << content.nodeTag[n];
      for (double v : {p.x, p.y, p.z}) {
        out << ", ";
        writeShortestReal(out, v);
      }
      out << '\n';
    }
}

// Elements numbered from 1 in the content's order; returns the first number of each block (0
// for the point blocks, which are not written).
std::vector<std::uint64_t> writeElements(std::ostream& out, const MshContent& content) {
  std::vector<std::uint64_t> first;
  std::uint64_t number = 0;
  std::vector<std::uint64_t> line;
  for (const MshElementBlock& b : content.elementBlocks) {
    const InpElement* inp = inpElementOf(b.block->type);
    first.push_back(inp ? number + 1 : 0);
    if (!inp) continue;
    out << "*ELEMENT, TYPE=" << inp->name << ", ELSET=" << entityName(b.entity) << '\n';
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      const auto nodes = b.block->element(i);
      line.assign(1, ++number);
      for (int k : inp->fromMsh) line.push_back(content.nodeTag[nodes[k]]);
      writeDataLines(out, line);
    }
  }
  return first;
}

void writeSets(std::ostream& out, const Model& model, const MshContent& content,
               const std::vector<std::uint64_t>& firstElement, const MeshWriteOptions& options) {
  for (const auto& [id, group] : model.physicalGroups()) {
    const std::vector<std::size_t> blocks = groupBlocks(content, group);
    std::vector<std::uint64_t> elements;
    for (std::size_t i : blocks)
      for (std::size_t e = 0; firstElement[i] != 0 && e < content.elementBlocks[i].block->size();
           ++e)
        elements.push_back(firstElement[i] + e);
    const std::string name = setName(physicalGroupName(group));
    if (savesGroupsOfDimension(options.saveGroupsOfElements, group.dim) && !elements.empty()) {
      out << "*ELSET, ELSET=" << name << '\n';
      writeDataLines(out, elements);
    }
    const std::vector<std::uint64_t> nodes = groupNodeTags(content, blocks);
    if (savesGroupsOfDimension(options.saveGroupsOfNodes, group.dim) && !nodes.empty()) {
      out << "*NSET, NSET=" << name << '\n';
      writeDataLines(out, nodes);
    }
  }
}

}  // namespace

// Named by the inp row of io/formats.cpp. Saves what an MSH file would, except point elements
// (their nodes are saved, and a group of points can be a node set).
void writeInp(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const MshContent content = selectMshContent(model, mesh, options.saveAll);
  for (const MshElementBlock& b : content.elementBlocks) inpElementOf(b.block->type);
  out << "*HEADING\ngeomesh mesh\n";
  writeNodes(out, mesh, content);
  const std::vector<std::uint64_t> firstElement = writeElements(out, content);
  writeSets(out, model, content, firstElement, options);
}

}  // namespace geomesh
