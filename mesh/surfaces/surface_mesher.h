// meshSurface and the Mesh.Algorithm codes: one surface meshed in its parameter plane.
#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/sizes/size_field.h"
#include "mesh/core/mesh.h"
#include "mesh/sizes/size_rules.h"
#include "mesh/surfaces/anisotropic_mesh.h"
#include "mesh/surfaces/surface_algorithms.h"

namespace geomesh {

// Meshes one surface whose boundary (and embedded) curves and points are meshed already, starting
// from the constrained Delaunay triangulation of the boundary nodes in the parameter plane, which
// `algorithm` (a row of surfaceAlgorithms() that has a function) fills, with `smoothingPasses`
// passes of smoothing. Target sizes are extended from the boundary nodes' target sizes
// (Mesh::nodeSize), and the new nodes get theirs; with a background size field, the interior's
// target size is the smaller of the extended one and the field's. Curved surfaces are meshed in
// their own metric (first fundamental form), planes in plain lengths. No boundary node is added;
// the triangles are counter-clockwise in the surface's parametrization. Throws MeshError naming the
// surface when its boundary cannot be triangulated. `anisotropy` (Mesh.AnisoMax,
// Mesh.SmoothRatio) is read by the anisotropic algorithm (7) only.
void meshSurface(const Model& model, const ModelSurface& surface, const SizeRules& rules,
                 int smoothingPasses, Mesh& mesh, const SizeFields* fields,
                 const SurfaceAlgorithm& algorithm, const AnisotropicSettings& anisotropy = {});

}  // namespace geomesh
