// MSH 4.1: $Entities (and $PartitionedEntities), then $Nodes and $Elements in blocks, one block
// per entity (and element type). In binary files counts are size_t, tags in headers int, node
// and element tags size_t.
#include <cstdlib>

#include "io/msh_sections.h"

namespace geomesh {

namespace {

// Box of the nodes of an entity (or piece) and of its elements; the origin when it has none.
BoundingBox meshBox(const Mesh& mesh, const std::vector<NodeIndex>& nodes,
                    const std::vector<ElementBlock>& blocks) {
  BoundingBox box;
  for (NodeIndex n : nodes) box.include(mesh.node(n));
  for (const ElementBlock& b : blocks)
    for (NodeIndex n : b.nodes) box.include(mesh.node(n));
  if (box.empty()) box.include(Vec3{});
  return box;
}

// Bounding box of an entity: from its geometry when it has one, else from its mesh nodes.
BoundingBox entityBox(const Model& model, const Mesh& mesh, EntityId e) {
  const BoundingBox box = model.boundingBox(e);
  if (!box.empty()) return box;
  const EntityMesh* em = mesh.find(e);
  return em ? meshBox(mesh, em->nodes, em->blocks) : meshBox(mesh, {}, {});
}

void writeTagList(MshEncoder& out, const std::vector<int>& tags) {
  out.size(tags.size());
  for (int t : tags) out.integer(t);
}

// What follows the tag (and for pieces the parent and partitions) of an entity: its box (one
// corner for points), its physical groups and, above points, its bounding entities.
void writeBoxGroupsAndBoundary(MshEncoder& out, int dim, const BoundingBox& box,
                               const std::vector<int>& physicals,
                               const std::vector<int>& bounding) {
  out.real(box.min.x);
  out.real(box.min.y);
  out.real(box.min.z);
  if (dim > 0) {
    out.real(box.max.x);
    out.real(box.max.y);
    out.real(box.max.z);
  }
  writeTagList(out, physicals);
  if (dim > 0) writeTagList(out, bounding);
  out.endLine(true);
}

// Signed bounding entities as Gmsh lists them: a curve's start point positive, its end point
// negative; surfaces and volumes their loops' signed tags.
std::vector<int> boundingEntities(const Model& model, EntityId e) {
  if (e.dim != 1) return model.boundary(e);
  const ModelCurve* c = model.curve(e.tag);
  if (!c || c->startPoint == 0) return {};
  return {c->startPoint, -c->endPoint};
}

void writeEntity(MshEncoder& out, const Model& model, const Mesh& mesh, EntityId e) {
  out.integer(e.tag);
  writeBoxGroupsAndBoundary(out, e.dim, entityBox(model, mesh, e), model.physicalTagsOf(e),
                            e.dim > 0 ? boundingEntities(model, e) : std::vector<int>{});
}

void writeEntities(MshEncoder& out, const Model& model, const Mesh& mesh,
                   const MshContent& content) {
  std::size_t counts[4] = {};
  for (EntityId e : content.entities) ++counts[e.dim];
  out.text("$Entities\n");
  for (std::size_t c : counts) out.size(c);
  out.endLine();
  for (EntityId e : content.entities) writeEntity(out, model, mesh, e);
  endSection(out, "$EndEntities\n");
}

// $PartitionedEntities: the pieces, each with its parent entity and its partitions; no ghost
// entities.
void writePartitionedEntities(MshEncoder& out, const Mesh& mesh, const MshContent& content) {
  std::size_t counts[4] = {};
  for (const PartitionEntity* piece : content.pieces) ++counts[piece->id.dim];
  out.text("$PartitionedEntities\n");
  out.size(static_cast<std::size_t>(content.partitions->count));
  out.endLine();
  out.size(0);
  out.endLine();
  for (std::size_t c : counts) out.size(c);
  out.endLine();
  for (const PartitionEntity* piece : content.pieces) {
    out.integer(piece->id.tag);
    out.integer(piece->parent.dim);
    out.integer(piece->parent.tag);
    writeTagList(out, piece->partitions);
    writeBoxGroupsAndBoundary(out, piece->id.dim, meshBox(mesh, piece->nodes, piece->blocks),
                              piece->physicals, piece->boundary);
  }
  endSection(out, "$EndPartitionedEntities\n");
}

void writeNodes(MshEncoder& out, const Mesh& mesh, const MshContent& content) {
  out.text("$Nodes\n");
  out.size(content.nodeBlocks.size());
  out.size(content.nodeCount);
  out.size(content.nodeCount > 0 ? 1 : 0);
  out.size(content.nodeCount);
  out.endLine();
  for (const MshNodeBlock& block : content.nodeBlocks) {
    out.integer(block.entity.dim);
    out.integer(block.entity.tag);
    out.integer(0);  // no parametric coordinates
    out.size(block.nodes.size());
    out.endLine();
    for (NodeIndex n : block.nodes) {
      out.size(content.nodeTag[n]);
      out.endLine();
    }
    for (NodeIndex n : block.nodes) {
      const Vec3 p = mesh.node(n);
      out.real(p.x);
      out.real(p.y);
      out.real(p.z);
      out.endLine();
    }
  }
  endSection(out, "$EndNodes\n");
}

void writeElements(MshEncoder& out, const MshContent& content) {
  out.text("$Elements\n");
  out.size(content.elementBlocks.size());
  out.size(content.elementCount);
  out.size(content.elementCount > 0 ? 1 : 0);
  out.size(content.elementCount);
  out.endLine();
  std::uint64_t tag = 0;
  for (const MshElementBlock& b : content.elementBlocks) {
    out.integer(b.entity.dim);
    out.integer(b.entity.tag);
    out.integer(static_cast<int>(b.block->type));
    out.size(b.block->size());
    out.endLine();
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      out.size(++tag);
      for (NodeIndex n : b.block->element(i)) out.size(content.nodeTag[n]);
      out.endLine(true);
    }
  }
  endSection(out, "$EndElements\n");
}

}  // namespace

void writeMsh41Body(MshEncoder& out, const Model& model, const Mesh& mesh,
                    const MshContent& content) {
  writeEntities(out, model, mesh, content);
  if (content.partitions) writePartitionedEntities(out, mesh, content);
  writeNodes(out, mesh, content);
  writeElements(out, content);
  writePeriodic(out, mesh, content, false);
}

}  // namespace geomesh
