// generateMesh: meshes a model up to a dimension, stage by stage.
#pragma once

#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_error.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

// Meshes the model up to `dim` (0: points only, 1: curves, 2: surfaces, 3: volumes), replacing
// what `mesh` held. Each stage reports one line with its wall time to `log`.
void generateMesh(const Model& model, const MeshOptions& options, int dim, Mesh& mesh,
                  MessageSink& log);

// Gives the mesh the order options.elementOrder (SetOrder n; and the end of generateMesh),
// with one timing line on `log`.
void raiseOrder(const Model& model, const MeshOptions& options, Mesh& mesh, MessageSink& log);

}  // namespace geomesh
