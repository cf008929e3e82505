// The triangles of a mesh's surface elements as one triangulation (shared nodes shared), and
// its connected parts: what the curvature plugins and the check of a surface mesh work on.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/core/mesh.h"
#include "mesh/discrete/triangulation.h"

namespace geomesh {

// The 2D elements of every entity of `mesh`, in the order of its entities and blocks:
// triangles as they are, quadrangles split in two, high-order elements by their corners.
// Elements of different entities that share a node share the vertex; nodes no 2D element
// uses are left out.
struct MeshTriangles {
  Triangulation triangulation;
  std::vector<NodeIndex> node;  // per vertex: the mesh node it is
};
MeshTriangles meshTriangles(const Mesh& mesh);

// The parts of `t` connected through shared vertices, each with its own vertices (in the
// order of first use), in the order of their first triangle.
std::vector<Triangulation> connectedParts(const Triangulation& t);

}  // namespace geomesh
