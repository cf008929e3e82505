// Messages of meshing failures.
#include "mesh/core/mesh_error.h"

namespace geomesh {

std::string entityName(EntityId e) {
  static constexpr const char* kNames[4] = {"point", "curve", "surface", "volume"};
  const char* name = e.dim >= 0 && e.dim < 4 ? kNames[e.dim] : "entity";
  return std::string(name) + " " + std::to_string(e.tag);
}

MeshError::MeshError(EntityId e, const std::string& reason)
    : std::runtime_error("cannot mesh " + entityName(e) + ": " + reason), entity(e) {}

}  // namespace geomesh
