// estimateTetrahedra: how many tetrahedra a volume will get, to refuse what memory cannot hold.
#pragma once

#include <string>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/core/mesh_options.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

// The number of tetrahedra refinement will make in the volume the complex's shells enclose
// (the outer one's volume less the inner ones'), at the mean edge length of its triangles and
// quadrangles, within options.sizeMin/sizeMax, averaged over the shells' area: about 4.7 per
// cube of that size, as measured on boxes (within 30%; graded sizes make it an overestimate,
// sizes from a field inside an underestimate).
double estimateTetrahedra(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                          const MeshOptions& options);

// Why `tetrahedra` are more than this machine can mesh (its physical memory at about 150 bytes
// per tetrahedron while meshing, or the 1e9 tetrahedra a volume can number), or empty.
std::string tooManyTetrahedra(double tetrahedra);

}  // namespace geomesh
