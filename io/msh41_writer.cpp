// MSH 4.1: $Entities, then $Nodes and $Elements in blocks, one block per entity (and element
// type). In binary files counts are size_t, tags in headers int, node and element tags size_t.
#include <cstdlib>

#include "io/msh_sections.h"

namespace geomesh {

namespace {

// Bounding box of an entity: from its geometry when it has one, else from its mesh nodes.
BoundingBox entityBox(const Model& model, const Mesh& mesh, EntityId e) {
  BoundingBox box = model.boundingBox(e);
  if (!box.empty()) return box;
  if (const EntityMesh* em = mesh.find(e)) {
    for (NodeIndex n : em->nodes) box.include(mesh.node(n));
    for (const ElementBlock& b : em->blocks)
      for (NodeIndex n : b.nodes) box.include(mesh.node(n));
  }
  if (box.empty()) box.include(Vec3{});
  return box;
}

void writeTagList(MshEncoder& out, const std::vector<int>& tags) {
  out.size(tags.size());
  for (int t : tags) out.integer(t);
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
  const BoundingBox box = entityBox(model, mesh, e);
  out.real(box.min.x);
  out.real(box.min.y);
  out.real(box.min.z);
  if (e.dim > 0) {
    out.real(box.max.x);
    out.real(box.max.y);
    out.real(box.max.z);
  }
  writeTagList(out, model.physicalTagsOf(e));
  if (e.dim > 0) writeTagList(out, boundingEntities(model, e));
  out.endLine(true);
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
  writeNodes(out, mesh, content);
  writeElements(out, content);
  writePeriodic(out, mesh, content, false);
}

}  // namespace geomesh
