#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/sizes/size_field.h"
#include "mesh/core/mesh.h"
#include "mesh/sizes/size_rules.h"

namespace geomesh {

// Mesh.Algorithm values.
namespace algorithm2d {
inline constexpr int kMeshAdapt = 1;
inline constexpr int kAutomatic = 2;
inline constexpr int kInitialMeshOnly = 3;
inline constexpr int kDelaunay = 5;
inline constexpr int kFrontalDelaunay = 6;
inline constexpr int kBamg = 7;
inline constexpr int kFrontalDelaunayQuads = 8;
inline constexpr int kPacking = 9;
inline constexpr int kQuasiStructuredQuads = 11;
}  // namespace algorithm2d

// Meshes one surface whose boundary (and embedded) curves and points are meshed already,
// starting from the constrained Delaunay triangulation of the boundary nodes in the
// parameter plane. `algorithm2D` says what follows: MeshAdapt (1, local modifications, see
// adaptMesh), nothing (3, the boundary triangulation only), frontal-Delaunay for quadrangles
// (8, square cells split in two, not smoothed), or Delaunay (5) or frontal-Delaunay (6, any
// other value) refinement to the target size followed by `smoothingPasses` passes of
// smoothing. Target sizes are extended from the boundary nodes' sizes in nodeSizes; with a
// background size field, the interior's target size is the smaller of the extended one and
// the field's. Curved surfaces are meshed in their own metric (first fundamental form),
// planes in plain lengths. No boundary node is added; the triangles are counter-clockwise in
// the surface's parametrization. Throws MeshError naming the surface when its boundary
// cannot be triangulated.
void meshSurface(const Model& model, const ModelSurface& surface, const SizeRules& rules,
                 int smoothingPasses, Mesh& mesh, std::vector<double>& nodeSizes,
                 const SizeFields* fields = nullptr,
                 int algorithm2D = algorithm2d::kFrontalDelaunay);

}  // namespace geomesh
