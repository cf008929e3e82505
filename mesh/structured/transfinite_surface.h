// meshTransfiniteSurface: the structured mesh of a 3- or 4-sided Transfinite Surface.
#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_error.h"

namespace geomesh {

// Meshes a surface of 3 or 4 sides (Transfinite Surface) whose boundary curves are meshed:
// the sides run between the corners (given, else the start points of the loop's 3 or 4
// curves); opposite sides must have as many nodes. The grid of nodes comes from transfinite
// (Coons) interpolation of the boundary nodes in the parameter plane. Cells are split into two
// triangles along the diagonal `arrangement` asks for, or kept as quadrangles (Quad4) when
// `recombine`; on a 3-sided surface the cells at the first corner are triangles. Elements
// are counter-clockwise in the surface's parametrization. Throws MeshError naming the surface
// when its boundary does not fit.
// Thrown by meshTransfiniteSurface, before it changes the mesh, when opposite sides have
// different numbers of nodes: the reference then meshes the surface as if not transfinite.
class TransfiniteSidesMismatch : public MeshError {
 public:
  TransfiniteSidesMismatch(EntityId e, const std::string& why) : MeshError(e, why), reason(why) {}
  std::string reason;
};

void meshTransfiniteSurface(const Model& model, const ModelSurface& surface,
                            const TransfiniteSurface& constraint, bool recombine, Mesh& mesh);

}  // namespace geomesh
