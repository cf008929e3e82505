// meshVolume: the tetrahedral mesh of one volume by TetGen, boundary triangles kept.
#pragma once

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

// Meshes one volume with tetrahedra (TetGen), from the triangle meshes of the surfaces of its
// shells, which `mesh` must hold already. The boundary triangles are kept exactly (no node is
// added on the boundary); interior nodes are added to the volume's EntityMesh and sized from the
// boundary edge lengths, bounded by options.sizeMin/sizeMax. Inner shells are holes. The
// Tet4 elements are positively oriented. Throws MeshError naming the volume on failure
// (missing or non-triangular surface mesh, intersecting boundary, TetGen failure).
void meshVolume(const Model& model, const MeshOptions& options, int volumeTag, Mesh& mesh);

}  // namespace geomesh
