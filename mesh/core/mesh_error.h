// The error every mesher throws when it cannot mesh an entity.
#pragma once

#include <stdexcept>
#include <string>

#include "kernel/model.h"

namespace geomesh {

// Meshing an entity failed; `entity` names it (the message reads "cannot mesh surface 3: ...").
class MeshError : public std::runtime_error {
 public:
  MeshError(EntityId e, const std::string& reason);
  EntityId entity;
};

// "point 1", "curve 2", "surface 3", "volume 4".
std::string entityName(EntityId e);

}  // namespace geomesh
