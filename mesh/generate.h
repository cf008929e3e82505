#pragma once

#include <stdexcept>
#include <string>

#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/mesh.h"
#include "mesh/mesh_options.h"

namespace geomesh {

// Meshing an entity failed; `entity` names it.
class MeshError : public std::runtime_error {
 public:
  MeshError(EntityId e, const std::string& reason);
  EntityId entity;
};

// Meshes the model up to `dim` (0: points only, 1: curves, 2: surfaces, 3: volumes), replacing
// what `mesh` held. Each stage reports one line with its wall time to `log`.
void generateMesh(const Model& model, const MeshOptions& options, int dim, Mesh& mesh,
                  MessageSink& log);

}  // namespace geomesh
