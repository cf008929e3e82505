// selectSurfaceContent: the triangles and quadrangles of surface-only formats, checked first;
// their named parts and their ASCII vertex and face lists.
#include "io/surface_content.h"

#include <cstdlib>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/physical_sets.h"
#include "io/real_text.h"

namespace geomesh {

namespace {

// "1200 hexahedron and 40 line elements"
std::string describeCounts(const std::map<ElementType, std::size_t>& counts) {
  std::string text;
  std::size_t i = 0;
  for (const auto& [type, n] : counts) {
    if (i > 0) text += i + 1 == counts.size() ? " and " : ", ";
    text += std::to_string(n) + " " + elementName(type);
    ++i;
  }
  return text + " elements";
}

void checkTypes(const MshContent& content, std::string_view format) {
  std::map<ElementType, std::size_t> counts;
  bool surface = false;
  for (const MshElementBlock& b : content.elementBlocks) {
    const ElementType type = b.block->type;
    counts[type] += b.block->size();
    if (dimension(type) != 2) continue;
    surface = true;
    if (order(type) > 1)
      throw std::invalid_argument(std::string(format) + " files hold elements up to order 1: " +
                                  "the mesh to save has " + describeCounts({{type, counts[type]}}) +
                                  " of order " + std::to_string(order(type)));
  }
  if (!surface && !counts.empty())
    throw std::invalid_argument(std::string(format) +
                                " files hold surface elements only: the mesh to save has " +
                                describeCounts(counts) + " and no surface element");
}

}  // namespace

SurfaceContent selectSurfaceContent(const Model& model, const Mesh& mesh, bool saveAll,
                                    std::string_view format) {
  SurfaceContent surface{selectMshContent(model, mesh, saveAll), {}, {}, {}, 0};
  checkTypes(surface.content, format);
  constexpr std::uint32_t kUnused = ~std::uint32_t{0};
  surface.indexOfNode.assign(mesh.nodeCount(), kUnused);
  for (const MshElementBlock& b : surface.content.elementBlocks) {
    if (dimension(b.block->type) != 2) continue;
    surface.blocks.push_back(b);
    surface.faceCount += b.block->size();
    for (NodeIndex n : b.block->nodes) surface.indexOfNode[n] = 0;
  }
  for (const MshNodeBlock& block : surface.content.nodeBlocks)
    for (NodeIndex n : block.nodes)
      if (surface.indexOfNode[n] != kUnused) {
        surface.indexOfNode[n] = static_cast<std::uint32_t>(surface.nodes.size());
        surface.nodes.push_back(n);
      }
  return surface;
}

std::vector<NamedSurfacePart> namedSurfaceParts(const Model& model,
                                                const SurfaceContent& surface) {
  std::vector<NamedSurfacePart> parts;
  if (!surface.content.physicalOnly) {
    for (const MshElementBlock& b : surface.blocks) {
      const std::string name = "surface" + std::to_string(b.entity.tag);
      if (parts.empty() || parts.back().name != name) parts.push_back({name, {}});
      parts.back().blocks.push_back(b.block);
    }
    return parts;
  }
  for (const auto& [id, group] : model.physicalGroups()) {
    if (id.dim != 2) continue;
    NamedSurfacePart part{physicalGroupName(group), {}};
    for (const MshElementBlock& b : surface.blocks)
      for (int tag : group.entities)
        if (b.entity.tag == std::abs(tag)) part.blocks.push_back(b.block);
    if (!part.blocks.empty()) parts.push_back(std::move(part));
  }
  return parts;
}

void writeAsciiVerticesAndFaces(std::ostream& out, const Mesh& mesh,
                                const SurfaceContent& surface) {
  for (NodeIndex n : surface.nodes) {
    const Vec3 p = mesh.node(n);
    writeShortestReal(out, p.x);
    out << ' ';
    writeShortestReal(out, p.y);
    out << ' ';
    writeShortestReal(out, p.z);
    out << '\n';
  }
  for (const MshElementBlock& b : surface.blocks)
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      const auto nodes = b.block->element(i);
      out << nodes.size();
      for (NodeIndex n : nodes) out << ' ' << surface.indexOfNode[n];
      out << '\n';
    }
}

}  // namespace geomesh
