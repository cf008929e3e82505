// embeddedConformityDefects: where a volume's tetrahedra fail the entities embedded in it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// How the tetrahedra `tets` (4 nodes each) of `volume` fail to conform to the entities
// embedded in it: each triangle of an embedded surface must be a face of exactly two
// tetrahedra, one on each side; each segment of an embedded curve an edge of the tetrahedra;
// each embedded point one of their nodes. One sentence per defect, naming the embedded entity
// and a place near it; at most `limit` of them. Empty when the tetrahedra conform.
std::vector<std::string> embeddedConformityDefects(const ModelVolume& volume, const Mesh& mesh,
                                                   const ElementBlock& tets, std::size_t limit);

}  // namespace geomesh
