// meshVolume: the tetrahedral mesh of one volume by TetGen, boundary triangles kept.
#pragma once

#include <functional>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

// The size asked for at a point inside a volume.
using InteriorSize = std::function<double(Vec3)>;

// Meshes one volume with tetrahedra (TetGen), from the triangle meshes of the surfaces of its
// shells, which `mesh` must hold already. The boundary triangles are kept exactly (no node is
// added on the boundary); interior nodes are added to the volume's EntityMesh and sized from the
// boundary edge lengths, bounded by options.sizeMin/sizeMax. Inner shells are holes. The
// entities embedded in the volume are kept exactly too: each triangle of an embedded surface is
// a face of two tetrahedra, one each side, each segment of an embedded curve an edge, each
// embedded point a node; the embedded surfaces' sizes spread into the volume as the boundary's
// do, while embedded curves and points, as in the reference, take the size of the nearest
// surface node. The Tet4 elements are positively oriented. Throws MeshError naming the volume
// on failure (missing or non-triangular surface mesh, intersecting boundary, an embedded entity
// crossing the boundary or another one, or lying outside the volume, TetGen failure).
// With `interiorSize` (the background field's size at a point, or null), the tetrahedra are
// then refined until they follow it inside too: the mesh is made again a few times, each time
// sized by the field evaluated at the nodes of the previous one (bounded by the boundary's
// sizes when options.sizeExtendFromBoundary).
void meshVolume(const Model& model, const MeshOptions& options, int volumeTag,
                const InteriorSize& interiorSize, Mesh& mesh);

}  // namespace geomesh
