// addDiscreteEntities: model entities and node classification for meshes read from files.
#include "io/discrete_mesh.h"

namespace geomesh {

namespace {

void addEntity(Model& model, const Mesh& mesh, const EntityMesh& em) {
  const int tag = em.entity.tag;
  switch (em.entity.dim) {
    case 0: {
      const ElementBlock* block = em.findBlock(ElementType::Point1);
      const Vec3 xyz = block && block->size() > 0 ? mesh.node(block->nodes.front()) : Vec3{};
      model.addPoint({tag, xyz, 0});
      break;
    }
    case 1: model.addCurve({tag, 0, 0, nullptr}); break;
    case 2: model.addSurface({tag, {}, nullptr, {}, {}}); break;
    default: model.addVolume({tag, {}}); break;
  }
}

}  // namespace

void addDiscreteEntities(Model& model, Mesh& mesh, std::vector<PhysicalGroup> groups) {
  std::vector<char> classified(mesh.nodeCount(), 0);
  std::vector<EntityId> ids;
  for (const auto& [id, em] : mesh.entities())
    if (em.elementCount() > 0) ids.push_back(id);
  for (EntityId id : ids) {  // by increasing dimension
    EntityMesh& em = mesh.entity(id);
    for (const ElementBlock& b : em.blocks)
      for (NodeIndex n : b.nodes)
        if (!classified[n]) {
          classified[n] = 1;
          em.nodes.push_back(n);
        }
    addEntity(model, mesh, em);
  }
  mesh.dropUnheldNodes();
  for (PhysicalGroup& group : groups) model.addPhysicalGroup(std::move(group));
}

void readReplacing(Model& model, Mesh& mesh, const std::function<void()>& read) {
  model.clear();
  mesh.clear();
  try {
    read();
  } catch (...) {
    model.clear();
    mesh.clear();
    throw;
  }
}

}  // namespace geomesh
