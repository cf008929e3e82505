// What checkMesh needs for high-order elements: their first-order view, and the conformity
// of the nodes inside their edges.
#pragma once

#include <map>
#include <vector>

#include "mesh/checks/mesh_check.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// True when some element of `mesh` has an order above 1.
bool hasHighOrderElements(const Mesh& mesh);

// The entity meshes holding high-order elements, each element cut down to its corners (the
// first vertexCount nodes) in a block of the family's first-order type; nodes, parameters and
// periodic links copied as they are. Entities with first-order elements only are left out.
std::map<EntityId, EntityMesh> cornerMeshes(const Mesh& mesh);

// Two elements that share an edge (a pair of corner nodes) must have the same nodes inside it,
// in the same order from one end to the other, whatever direction each element runs along it;
// a first-order element has none. Covers elements of every dimension, so that a curve's lines
// agree with the triangles along it. At most `maxProblems` problems are added.
void checkEdgeNodes(const Mesh& mesh, std::size_t maxProblems, std::vector<MeshProblem>& out);

}  // namespace geomesh
