// The mesh of discrete entities (merged triangulations), copied rather than generated.
#pragma once

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Copies into `mesh` the elements of the model's discrete entities from the merged file's mesh
// `from`: the corners ClassifySurfaces found (as points), the curves along them and, from
// `dim` 2, the surfaces that CreateGeometry did not give a geometry. Their nodes are shared as
// in `from`; each node's target size is the mean length of its edges, which the meshers of
// the other entities grade from. Throws MeshError for an entity `from` holds nothing of.
void copyDiscreteEntities(const Model& model, const Mesh& from, int dim, Mesh& mesh);

// A volume bounded by discrete surfaces needs their triangles to close: every edge of the
// shells' triangles in exactly two of them. Throws MeshError naming the volume and an edge.
void checkDiscreteShells(const Model& model, const Mesh& mesh);

}  // namespace geomesh
