// I-DEAS universal files (.unv): nodes (dataset 2411), elements (2412) and, per physical group,
// a group of its elements and/or nodes (2477) as Mesh.SaveGroupsOfElements/Nodes select.
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "io/formats.h"
#include "io/msh_content.h"
#include "io/physical_sets.h"
#include "io/unv_elements.h"

namespace geomesh {

namespace {

constexpr const char* kDelimiter = "    -1\n";

// A real as I-DEAS writes it (FORTRAN 1PD25.16): D exponent, 25 columns.
void writeUnvReal(std::ostream& out, double v) {
  char text[40];
  const int n = std::snprintf(text, sizeof text, "%25.16E", v);
  for (int i = 0; i < n; ++i)
    if (text[i] == 'E') text[i] = 'D';
  out.write(text, n);
}

void writeInts(std::ostream& out, std::initializer_list<long long> values) {
  char text[16];
  for (long long v : values) out.write(text, std::snprintf(text, sizeof text, "%10lld", v));
  out << '\n';
}

void writeNodes(std::ostream& out, const Mesh& mesh, const MshContent& content) {
  out << kDelimiter << "  2411\n";
  for (const MshNodeBlock& block : content.nodeBlocks)
    for (NodeIndex n : block.nodes) {
      // Export and displacement coordinate systems 1, colour 11.
      writeInts(out, {static_cast<long long>(content.nodeTag[n]), 1, 1, 11});
      const Vec3 p = mesh.node(n);
      writeUnvReal(out, p.x);
      writeUnvReal(out, p.y);
      writeUnvReal(out, p.z);
      out << '\n';
    }
  out << kDelimiter;
}

// Node labels, eight to a line.
void writeNodeList(std::ostream& out, const std::vector<long long>& labels) {
  char text[16];
  for (std::size_t i = 0; i < labels.size(); ++i) {
    out.write(text, std::snprintf(text, sizeof text, "%10lld", labels[i]));
    if (i % 8 == 7 || i + 1 == labels.size()) out << '\n';
  }
}

// Writes the elements, numbered from 1 in the content's order; returns the first number of
// each block (0 for the point blocks, which are not written).
std::vector<long long> writeElements(std::ostream& out, const MshContent& content) {
  out << kDelimiter << "  2412\n";
  std::vector<long long> first;
  long long label = 0;
  for (const MshElementBlock& b : content.elementBlocks) {
    first.push_back(b.block->type == ElementType::Point1 ? 0 : label + 1);
    if (b.block->type == ElementType::Point1) continue;
    const UnvElement& unv = unvElementForWriting(b.block->type);
    std::vector<long long> labels(unv.fromMsh.size());
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      // Physical property table: the entity; material table: none (Gmsh's reader would take
      // it for a physical group and drop the name the group's dataset gives); colour 7.
      writeInts(out, {++label, unv.descriptor, b.entity.tag, 0, 7,
                      static_cast<long long>(labels.size())});
      if (unvHasBeamRecord(unv.descriptor)) writeInts(out, {0, 0, 0});
      const auto nodes = b.block->element(i);
      for (std::size_t k = 0; k < labels.size(); ++k)
        labels[k] = static_cast<long long>(content.nodeTag[nodes[unv.fromMsh[k]]]);
      writeNodeList(out, labels);
    }
  }
  out << kDelimiter;
  return first;
}

// (entity type code, label): 7 a node, 8 an element.
using GroupEntry = std::pair<int, long long>;

std::vector<GroupEntry> groupEntries(const MshContent& content, const PhysicalGroup& group,
                                     const std::vector<long long>& firstElement,
                                     const MeshWriteOptions& options) {
  const std::vector<std::size_t> blocks = groupBlocks(content, group);
  std::vector<GroupEntry> entries;
  if (savesGroupsOfDimension(options.saveGroupsOfNodes, group.dim))
    for (std::uint64_t tag : groupNodeTags(content, blocks))
      entries.emplace_back(7, static_cast<long long>(tag));
  if (savesGroupsOfDimension(options.saveGroupsOfElements, group.dim))
    for (std::size_t i : blocks)
      if (firstElement[i] != 0)
        for (std::size_t e = 0; e < content.elementBlocks[i].block->size(); ++e)
          entries.emplace_back(8, firstElement[i] + static_cast<long long>(e));
  return entries;
}

void writeGroups(std::ostream& out, const Model& model, const MshContent& content,
                 const std::vector<long long>& firstElement, const MeshWriteOptions& options) {
  bool started = false;
  for (const auto& [id, group] : model.physicalGroups()) {
    const std::vector<GroupEntry> entries = groupEntries(content, group, firstElement, options);
    if (entries.empty()) continue;
    if (!started) out << kDelimiter << "  2477\n";
    started = true;
    writeInts(out, {group.tag, 0, 0, 0, 0, 0, 0, static_cast<long long>(entries.size())});
    out << physicalGroupName(group) << '\n';
    char text[48];
    for (std::size_t i = 0; i < entries.size(); ++i) {
      out.write(text, std::snprintf(text, sizeof text, "%10d%10lld%10d%10d", entries[i].first,
                                    entries[i].second, 0, 0));
      if (i % 2 == 1 || i + 1 == entries.size()) out << '\n';
    }
  }
  if (started) out << kDelimiter;
}

}  // namespace

// Named by the unv row of io/formats.cpp. Saves what an MSH file would, except point elements
// (their nodes are saved).
void writeUnv(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const MshContent content = selectMshContent(model, mesh, options.saveAll);
  for (const MshElementBlock& b : content.elementBlocks)
    if (b.block->type != ElementType::Point1) unvElementForWriting(b.block->type);
  writeNodes(out, mesh, content);
  const std::vector<long long> firstElement = writeElements(out, content);
  writeGroups(out, model, content, firstElement, options);
}

}  // namespace geomesh
