#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/fields/size_field.h"
#include "mesh/mesh.h"
#include "mesh/size_rules.h"

namespace geomesh {

// Meshes one surface whose boundary (and embedded) curves and points are meshed already:
// constrained Delaunay triangulation of the boundary nodes in the parameter plane, frontal-
// Delaunay (algorithm2D 6) or Delaunay (5) refinement to the target size (extended from the
// boundary nodes' sizes in nodeSizes), then `smoothingPasses` passes of smoothing. Curved
// surfaces are refined in their own metric (first fundamental form), planes in plain lengths.
// No boundary node is added; the triangles are counter-clockwise in the surface's
// parametrization. Throws MeshError naming the surface when its boundary cannot be
// triangulated. With a background size field, the interior's target size is the smaller of
// the extended one and the field's.
void meshSurface(const Model& model, const ModelSurface& surface, const SizeRules& rules,
                 int smoothingPasses, Mesh& mesh, std::vector<double>& nodeSizes,
                 const SizeFields* fields = nullptr, int algorithm2D = 6);

}  // namespace geomesh
