// MSH 2.2: a flat node list and a flat element list; each element carries two tags (physical
// group, entity). An element of an entity in several physical groups is written once per group.
#include <map>

#include "io/msh_sections.h"

namespace geomesh {

namespace {

void writeNodes(MshEncoder& out, const Mesh& mesh, const MshContent& content) {
  out.text("$Nodes\n" + std::to_string(content.nodeCount) + "\n");
  for (const MshNodeBlock& block : content.nodeBlocks)
    for (NodeIndex n : block.nodes) {
      const Vec3 p = mesh.node(n);
      out.integer(static_cast<int>(content.nodeTag[n]));
      out.real(p.x);
      out.real(p.y);
      out.real(p.z);
      out.endLine();
    }
  endSection(out, "$EndNodes\n");
}

// An element block and the physical tags its elements are written under (0: none).
struct ElementRun {
  const MshElementBlock* block;
  std::vector<int> physicals;
};

// Elements in the order Gmsh lists them: by dimension, then element type, then entity.
std::vector<ElementRun> elementRuns(const Model& model, const MshContent& content,
                                    bool physicalOnly) {
  std::map<std::pair<int, int>, std::vector<ElementRun>> byDimAndType;
  for (const MshElementBlock& b : content.elementBlocks) {
    auto& runs = byDimAndType[{b.entity.dim, static_cast<int>(b.block->type)}];
    runs.push_back({&b, physicalOnly ? model.physicalTagsOf(b.entity) : std::vector<int>{0}});
  }
  std::vector<ElementRun> out;
  for (auto& [key, runs] : byDimAndType) out.insert(out.end(), runs.begin(), runs.end());
  return out;
}

std::size_t lineCount(const std::vector<ElementRun>& runs, std::size_t from, std::size_t to) {
  std::size_t n = 0;
  for (std::size_t i = from; i < to; ++i)
    n += runs[i].block->block->size() * runs[i].physicals.size();
  return n;
}

// In binary, each element comes with its own header (type, count 1, tag count), as Gmsh
// writes it; the format also allows longer groups.
void writeElement(MshEncoder& out, const MshContent& content, int tag, int physical,
                  const MshElementBlock& b, std::size_t i) {
  const int type = static_cast<int>(b.block->type);
  if (out.binary()) {
    out.integer(type);
    out.integer(1);
    out.integer(2);
    out.integer(tag);
  } else {
    out.integer(tag);
    out.integer(type);
    out.integer(2);
  }
  out.integer(physical);
  out.integer(b.entity.tag);
  for (NodeIndex n : b.block->element(i)) out.integer(static_cast<int>(content.nodeTag[n]));
  out.endLine();
}

void writeElementRuns(MshEncoder& out, const MshContent& content,
                      const std::vector<ElementRun>& runs) {
  int tag = 0;
  for (const ElementRun& run : runs)
    for (std::size_t i = 0; i < run.block->block->size(); ++i)
      for (int physical : run.physicals) writeElement(out, content, ++tag, physical, *run.block, i);
}

}  // namespace

void writeMsh22Body(MshEncoder& out, const Model& model, const Mesh& mesh,
                    const MshContent& content, bool saveAll) {
  writeNodes(out, mesh, content);
  const bool physicalOnly = !saveAll && !model.physicalGroups().empty();
  const std::vector<ElementRun> runs = elementRuns(model, content, physicalOnly);
  out.text("$Elements\n" + std::to_string(lineCount(runs, 0, runs.size())) + "\n");
  writeElementRuns(out, content, runs);
  endSection(out, "$EndElements\n");
  writePeriodic(out, mesh, content, true);
}

}  // namespace geomesh
