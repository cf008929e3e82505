// surfaceTopology: counts that say whether a merged triangulation is a clean closed (or open)
// manifold surface: components, boundary loops, Euler characteristic, genus, and the defects
// (non-manifold and inconsistently oriented edges, degenerate triangles).
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/discrete/triangulation.h"

namespace geomesh {

struct SurfaceTopologyReport {
  std::size_t vertices = 0, edges = 0, triangles = 0;  // vertices: those some triangle uses
  int components = 0;                                  // connected through shared vertices
  int boundaryLoops = 0;                               // cycles of edges used by one triangle
  int euler = 0;                                       // V - E + F
  int genus = 0;                                       // sum over components of (2 - chi_c - b_c)/2
  std::size_t nonManifoldEdges = 0;
  std::size_t inconsistentEdges = 0;    // edges whose two triangles run it in the same direction
  std::size_t degenerateTriangles = 0;  // zero area (up to rounding) or a repeated vertex
};

SurfaceTopologyReport surfaceTopology(const Triangulation& t);

// Per vertex of t: whether it lies on a boundary edge (one triangle) or a non-manifold edge
// (three or more).
std::vector<bool> boundaryVertices(const Triangulation& t);

}  // namespace geomesh
