// checkMesh and MeshCheckReport: a mesh's defects against its model, entity by entity.
#pragma once

#include <string>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// One defect of a mesh, attributed to the entity whose mesh has it ({-1, 0} when none does).
struct MeshProblem {
  EntityId entity;
  std::string message;
};

struct MeshCheckReport {
  std::vector<MeshProblem> problems;
  bool ok() const { return problems.empty(); }
  std::string summary() const;  // one line per problem, naming the entity
};

// Checks a mesh against its model:
//  - node indices in range, every node owned by exactly one entity, no two nodes at the same
//    place;
//  - curves: Line2 elements chained from the start point's node to the end point's node,
//    nodes on the curve geometry (at their parameter);
//  - surfaces: every triangle positively oriented with respect to the surface's normal
//    (du x dv) and not flat; each interior edge shared by exactly two triangles, the boundary
//    edges exactly the segments of the boundary curves (embedded curves: two triangles each);
//    triangles only use nodes of the surface and its closure; nodes on the surface;
//  - volumes: tetrahedra, prisms, pyramids and hexahedra with a positive Jacobian at every
//    corner, not small against the product of the corner's edge lengths; in volumes with any but tetrahedra, each element face shared by two elements or
//    equal to a triangle or quadrangle of a boundary surface, and each of those a face of an
//    element (without known boundary surfaces, as read from MSH 2.2: by one or two elements);
//  - entities embedded in a volume: each triangle of an embedded surface a face of two
//    tetrahedra on opposite sides, each segment of an embedded curve an edge of a tetrahedron,
//    each embedded point a node of one;
//  - periodic entities: each node paired with a master node is that node's affine image;
//  - high-order elements: every check above on their corners (the first vertexCount nodes), the
//    other nodes held like any node; elements sharing an edge have the same nodes inside it.
MeshCheckReport checkMesh(const Model& model, const Mesh& mesh);

// The volume checks of checkMesh alone: what meshing volumes is checked by before the mesh is
// kept, so that no flat or inverted element is ever written.
MeshCheckReport checkVolumeElements(const Model& model, const Mesh& mesh);

}  // namespace geomesh
