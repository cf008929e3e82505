// subdivideIntoQuadrangles and subdivideIntoHexahedra: Mesh.SubdivisionAlgorithm 1 and 2.
#pragma once

#include <string>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Mesh.SubdivisionAlgorithm 1: makes every surface element a quadrangle. Each curve segment is
// cut at its parametric middle; each triangle becomes 3 quadrangles and each quadrangle 4,
// through the middles of its edges (shared with neighbours and curves) and its centroid, new
// nodes being put back on the surface. Orientation is kept. Meant for meshes of dimension 2.
void subdivideIntoQuadrangles(const Model& model, Mesh& mesh);

// Mesh.SubdivisionAlgorithm 2, after meshing volumes: every element becomes hexahedra,
// quadrangles and lines. Curves and surfaces are split as by subdivideIntoQuadrangles; each
// tetrahedron becomes 4 hexahedra, each prism 6 and each hexahedron 8, one per corner, through
// the middles of its edges, the centres of its faces and its own centre (new nodes on curves
// and surfaces are put on them, those inside a volume are means of corners). The hexahedra
// have a positive Jacobian when their element had. A mesh with pyramids (which have no such
// split) or of an order above 1 is left as it is: the reason is returned, else an empty
// string.
std::string subdivideIntoHexahedra(const Model& model, Mesh& mesh);

}  // namespace geomesh
