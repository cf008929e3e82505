// Turning the elements a mesh file lists into discrete model entities, for the readers of the
// formats whose files name no entities of their own (VTK, STL, PLY, OFF, OBJ).
#pragma once

#include <functional>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Every entity of `mesh` that has elements becomes a model entity without geometry (a point at
// the node of its point element); each node used by an element is classified on the
// lowest-dimensional entity whose elements use it, and nodes no element uses are dropped.
// `groups` are added as the model's physical groups.
void addDiscreteEntities(Model& model, Mesh& mesh, std::vector<PhysicalGroup> groups = {});

// Clears `model` and `mesh`, then runs `read`; if it throws, clears them again (no half-read
// result) and lets the error through.
void readReplacing(Model& model, Mesh& mesh, const std::function<void()>& read);

}  // namespace geomesh
