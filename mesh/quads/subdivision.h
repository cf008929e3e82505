// subdivideIntoQuadrangles: Mesh.SubdivisionAlgorithm 1, all surface elements quadrangles.
#pragma once

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Mesh.SubdivisionAlgorithm 1: makes every surface element a quadrangle. Each curve segment is
// cut at its parametric middle; each triangle becomes 3 quadrangles and each quadrangle 4,
// through the middles of its edges (shared with neighbours and curves) and its centroid, new
// nodes being put back on the surface. Orientation is kept. Meant for meshes of dimension 2.
void subdivideIntoQuadrangles(const Model& model, Mesh& mesh);

}  // namespace geomesh
