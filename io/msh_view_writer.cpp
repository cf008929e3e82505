// A view written as MSH (4.1 or 2.2, ASCII): the mesh, then one data section per time step.
// A list-based view is first made a mesh of its own (nodes shared where coordinates are equal)
// with element-node data.
#include <array>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/msh_sections.h"
#include "io/msh_view_data.h"
#include "io/real_text.h"
#include "io/view_file_parts.h"

namespace geomesh {

using post::MeshData;

namespace {

// A list-based view as a mesh and element-node data over it.
struct ListMesh {
  Mesh mesh;
  MeshData data;
};

void checkListsWritable(const post::View& view) {
  const post::ElementList* first = nullptr;
  for (const post::ElementList& l : view.lists) {
    if (l.size() == 0) continue;
    if (first && (l.kind != first->kind || l.steps != first->steps))
      throw std::runtime_error("view '" + view.name +
                               "' mixes field kinds or step counts: MSH data sections cannot");
    if (l.nodesPerElement != listNodeCount(l.shape, l.order))
      throw std::runtime_error("view '" + view.name + "' has a list of " +
                               std::to_string(l.nodesPerElement) + "-node elements");
    first = &l;
  }
}

ListMesh meshOfLists(const post::View& view) {
  checkListsWritable(view);
  ListMesh out;
  std::map<std::array<double, 3>, NodeIndex> nodeAt;
  std::map<ElementType, const post::ElementList*> listOf;
  for (const post::ElementList& l : view.lists) {
    if (l.size() == 0) continue;
    const ElementType type = listElementType(l.shape, l.order);
    listOf[type] = &l;
    ElementBlock& block = out.mesh.entity({dimension(type), 1}).block(type);
    for (std::size_t k = 0; k < l.coordinates.size(); k += 3) {
      const std::array<double, 3> p{l.coordinates[k], l.coordinates[k + 1], l.coordinates[k + 2]};
      auto [it, added] = nodeAt.emplace(p, NodeIndex(out.mesh.nodeCount()));
      if (added) {
        out.mesh.addNode({p[0], p[1], p[2]});
        out.mesh.entity({dimension(type), 1}).nodes.push_back(it->second);
      }
      block.nodes.push_back(it->second);
    }
  }
  // Element tags follow the mesh's order (FileMeshTags): entity by entity, block by block.
  out.data.kind = MeshData::Kind::ElementNode;
  const int steps = view.stepCount();
  out.data.steps.resize(std::size_t(std::max(steps, 0)));
  std::uint64_t tag = 0;
  for (const auto& [id, em] : out.mesh.entities())
    for (const ElementBlock& b : em.blocks) {
      const post::ElementList& l = *listOf.at(b.type);
      out.data.components = l.components();
      const std::size_t perStep = std::size_t(l.nodesPerElement) * std::size_t(l.components());
      for (std::size_t e = 0; e < l.size(); ++e) {
        ++tag;
        for (int s = 0; s < steps; ++s) {
          MeshData::Step& step = out.data.steps[std::size_t(s)];
          step.tags.push_back(tag);
          step.counts.push_back(l.nodesPerElement);
          const double* v = l.values.data() + e * l.valuesPerElement() + std::size_t(s) * perStep;
          step.values.insert(step.values.end(), v, v + perStep);
        }
      }
    }
  for (int s = 0; s < steps; ++s) {
    out.data.steps[std::size_t(s)].index = s;
    if (std::size_t(s) < view.times.size())
      out.data.steps[std::size_t(s)].time = view.times[std::size_t(s)];
  }
  return out;
}

// The mesh as MSH text, with the file tag of each mesh tag (see FileMeshTags).
struct WrittenMesh {
  std::string text;
  std::vector<std::uint64_t> nodeTag;     // by mesh tag - 1
  std::vector<std::uint64_t> elementTag;  // by mesh tag - 1
};

WrittenMesh writeMeshPart(const Mesh& mesh, double version) {
  const Model model{};  // no groups: every element is saved
  MshWriteOptions options;
  options.saveAll = true;
  options.version = version;
  std::ostringstream text;
  writeMsh(text, model, mesh, options);
  WrittenMesh out{text.str(), {}, {}};
  // The node tags the writers give (in entity order), and the element tags read back rather
  // than predicted for each version's order.
  const MshContent content = selectMshContent(model, mesh, true);
  FileMeshTags tags;
  tags.nodesGiven = tags.hasNodes = true;
  for (std::size_t n = 0; n < content.nodeTag.size(); ++n)
    if (content.nodeTag[n] != 0) tags.nodes[content.nodeTag[n]] = n + 1;
  readMshDataSections(out.text, "(written mesh)", mesh, &tags);
  out.nodeTag.assign(mesh.nodeCount(), 0);
  for (const auto& [file, own] : tags.nodes) out.nodeTag[own - 1] = file;
  for (const auto& [file, own] : tags.elements) {
    if (out.elementTag.size() < own) out.elementTag.resize(own, 0);
    out.elementTag[own - 1] = file;
  }
  return out;
}

const char* sectionName(MeshData::Kind kind) {
  switch (kind) {
    case MeshData::Kind::Node:
      return "NodeData";
    case MeshData::Kind::Element:
      return "ElementData";
    case MeshData::Kind::ElementNode:
      return "ElementNodeData";
  }
  return "NodeData";
}

void writeDataSection(std::ostream& out, const std::string& name, const MeshData& data,
                      const MeshData::Step& step, const WrittenMesh& written) {
  const char* section = sectionName(data.kind);
  out << '$' << section << "\n1\n\"" << name << "\"\n1\n";
  writeShortestReal(out, step.time);
  out << "\n3\n" << step.index << '\n' << data.components << '\n' << step.tags.size() << '\n';
  const bool byNode = data.kind == MeshData::Kind::Node;
  const std::vector<std::uint64_t>& fileTag = byNode ? written.nodeTag : written.elementTag;
  std::size_t offset = 0;
  for (std::size_t k = 0; k < step.tags.size(); ++k) {
    const std::uint64_t own = step.tags[k];
    if (own == 0 || own > fileTag.size() || fileTag[own - 1] == 0)
      throw std::runtime_error("view '" + name + "' has data on " +
                               (byNode ? "node " : "element ") + std::to_string(own) +
                               ", which the mesh does not have");
    out << fileTag[own - 1];
    int perEntry = 1;
    if (data.kind == MeshData::Kind::ElementNode) {
      perEntry = step.counts[k];
      out << ' ' << perEntry;
    }
    for (int i = 0; i < perEntry * data.components; ++i) {
      out << ' ';
      writeShortestReal(out, step.values[offset++]);
    }
    out << '\n';
  }
  out << "$End" << section << '\n';
}

void writeMeshAndData(std::ostream& out, const std::string& name, const Mesh& mesh,
                      const MeshData& data, double version, bool dataOnly) {
  const WrittenMesh written = writeMeshPart(mesh, version);
  if (!dataOnly) out << written.text;
  for (const MeshData::Step& step : data.steps) writeDataSection(out, name, data, step, written);
}

}  // namespace

void writeMshView(std::ostream& out, const post::View& view, const Mesh& mesh, double version,
                  bool dataOnly) {
  if (view.meshData)
    return writeMeshAndData(out, view.name, mesh, *view.meshData, version, dataOnly);
  const ListMesh own = meshOfLists(view);
  writeMeshAndData(out, view.name, own.mesh, own.data, version, false);
}

}  // namespace geomesh
