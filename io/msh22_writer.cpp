// MSH 2.2: a flat node list and a flat element list; each element carries two tags (physical
// group, entity). An element of an entity in several physical groups is written once per group.
#include <map>

#include "io/msh_writer.h"

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

// An element block, the physical tags its elements are written under (0: none), and the tags
// after them: the entity's, then in partitioned files the number of partitions and their list.
struct ElementRun {
  const MshElementBlock* block;
  std::vector<int> physicals;
  std::vector<int> tags;
};

// Old-style partitioned files give the tag of the model entity a piece comes from, as readers
// of unpartitioned files expect; the new style gives the piece's own tag.
std::vector<int> tagsAfterPhysical(const MshElementBlock& b, bool partitionOldStyle) {
  if (!b.piece) return {b.entity.tag};
  const PartitionEntity& piece = *b.piece;
  const bool parentTag = partitionOldStyle && piece.parent.dim == piece.id.dim;
  std::vector<int> tags = {parentTag ? piece.parent.tag : piece.id.tag,
                           static_cast<int>(piece.partitions.size())};
  tags.insert(tags.end(), piece.partitions.begin(), piece.partitions.end());
  return tags;
}

std::vector<int> physicalsOf(const Model& model, const MshElementBlock& b) {
  return b.piece ? b.piece->physicals : model.physicalTagsOf(b.entity);
}

// Elements in the order Gmsh lists them: by dimension, then element type, then entity.
std::vector<ElementRun> elementRuns(const Model& model, const MshContent& content,
                                    bool physicalOnly, bool partitionOldStyle) {
  std::map<std::pair<int, int>, std::vector<ElementRun>> byDimAndType;
  for (const MshElementBlock& b : content.elementBlocks) {
    auto& runs = byDimAndType[{b.entity.dim, static_cast<int>(b.block->type)}];
    runs.push_back({&b, physicalOnly ? physicalsOf(model, b) : std::vector<int>{0},
                    tagsAfterPhysical(b, partitionOldStyle)});
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
                  const ElementRun& run, std::size_t i) {
  const ElementBlock& block = *run.block->block;
  const int type = static_cast<int>(block.type);
  const int tagCount = 1 + static_cast<int>(run.tags.size());
  if (out.binary()) {
    out.integer(type);
    out.integer(1);
    out.integer(tagCount);
    out.integer(tag);
  } else {
    out.integer(tag);
    out.integer(type);
    out.integer(tagCount);
  }
  out.integer(physical);
  for (int t : run.tags) out.integer(t);
  for (NodeIndex n : block.element(i)) out.integer(static_cast<int>(content.nodeTag[n]));
  out.endLine();
}

void writeElementRuns(MshEncoder& out, const MshContent& content,
                      const std::vector<ElementRun>& runs) {
  int tag = 0;
  for (const ElementRun& run : runs)
    for (std::size_t i = 0; i < run.block->block->size(); ++i)
      for (int physical : run.physicals) writeElement(out, content, ++tag, physical, run, i);
}

}  // namespace

void writeMsh22Body(MshEncoder& out, const Model& model, const Mesh& mesh,
                    const MshContent& content, const MshWriteOptions& options) {
  writeNodes(out, mesh, content);
  const std::vector<ElementRun> runs =
      elementRuns(model, content, content.physicalOnly, options.partitionOldStyle);
  out.text("$Elements\n" + std::to_string(lineCount(runs, 0, runs.size())) + "\n");
  writeElementRuns(out, content, runs);
  endSection(out, "$EndElements\n");
  writePeriodic(out, mesh, content, true);
}

}  // namespace geomesh
