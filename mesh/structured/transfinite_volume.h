// meshTransfiniteVolume: the structured hexahedral mesh of a six-faced volume (Transfinite
// Volume) from the grids of quadrangles on its faces.
#pragma once

#include <string>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Meshes volume `tag` with hexahedra when it is a topological hexahedron (6 faces, 12 curves,
// 8 corners) whose faces are already meshed as structured grids of quadrangles (Transfinite
// and Recombine Surface): the interior nodes are placed by transfinite interpolation of the
// six face grids, with the spacing of the edges. `corners` are the 8 corner points (the
// bottom face 1-2-3-4, then the top 5-6-7-8, 5 above 1), or empty to find them from the
// shape. Returns an empty string when done, else why the volume cannot be meshed this way
// (the mesh is then unchanged).
std::string meshTransfiniteVolume(const Model& model, int tag, const std::vector<int>& corners,
                                  Mesh& mesh);

}  // namespace geomesh
