// recombineTriangles, quadAngleQuality and smoothMixedMesh: triangles paired into quadrangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/geometry.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Pairs the triangles of a surface mesh into quadrangles (Recombine Surface, Mesh.RecombineAll).
// Two triangles sharing an edge that is not on the boundary make a candidate quadrangle when
// it is convex and every corner angle stays within `maxAngleDeviation` degrees of 90
// (Recombine Surface{..} = angle; 45 by default). Candidates are taken greedily, best
// corner-angle quality first, then completed by Edmonds' blossom algorithm into a matching
// with as many quadrangles as possible; Simple keeps to the angle bound, Blossom takes every
// convex pair as a candidate. Each triangle joins at most one quadrangle, unpaired triangles
// stay (pairLeftoverTriangles may then pair them). The Quad4
// elements keep the triangles' orientation. Returns the number of quadrangles made.
// Triangles are never joined across an edge of `keptEdges` (edge keys of curve segments,
// sorted: see edgeKey).
enum class RecombinationAlgorithm { Simple = 0, Blossom = 1 };
std::size_t recombineTriangles(const Mesh& mesh, EntityMesh& em, double maxAngleDeviation,
                               RecombinationAlgorithm algorithm,
                               const std::vector<std::uint64_t>& keptEdges = {});

// Joins the triangles recombination left alone, two at a time, into quadrangles: on a
// shortest path of elements from one to the nearest other (across sides not in `keptEdges`),
// the sides consecutive elements share get a middle node, and each element on the path is
// split into 2 or 3 quadrangles (a triangle or a quadrangle with adjacent split sides around
// a new centre node). New nodes lie on the surface, with their parameters. A pair whose split
// would make a quadrangle that is not convex is left as it is. Returns the pairs joined.
std::size_t pairLeftoverTriangles(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em,
                                  const std::vector<std::uint64_t>& keptEdges = {});

// The key of the edge between two nodes, whatever their order.
inline std::uint64_t edgeKey(NodeIndex a, NodeIndex b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// Corner-angle quality of a quadrangle: 1 - max |corner angle - 90 deg| / 90 deg, so 1 for a
// rectangle; -1 when it is not strictly convex with respect to `normal`.
double quadAngleQuality(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 normal);

// The least angle quality of a quadrangle recombination makes: no corner above 175 degrees. A
// corner of nearly 180 degrees is convex by a hair on a curved surface (near a pole, along a
// seam) and flat or inverted once the quadrangle is cut along its other diagonal.
inline constexpr double kMinQuadQuality = 5.0 / 90;

// Laplacian smoothing of the surface's own nodes over its triangles and quadrangles: each
// node moves towards the mean of its neighbours, then back onto the surface (its parameters
// updated); a move is kept only when the elements around the node stay valid (triangles not
// inverted, quadrangles convex).
void smoothMixedMesh(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em, int passes);

}  // namespace geomesh
