// recombineSurface and its stages: triangles paired into quadrangles, cleaned up, smoothed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

#include "kernel/geometry.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Pairs the triangles of a surface mesh into quadrangles (Recombine Surface, Mesh.RecombineAll).
// Two triangles sharing an edge that is not on the boundary make a candidate quadrangle when it
// is convex with no corner above 175 degrees (kMinQuadQuality); candidates are ranked by their
// corner-angle quality. Simple takes them greedily, best first, and leaves the triangles whose
// neighbours are all taken; Blossom completes the greedy pairs by Edmonds' blossom algorithm
// into a matching with as many quadrangles as possible. Each triangle joins at most one
// quadrangle; unpaired triangles stay (pairLeftoverTriangles may then pair them). The Quad4
// elements keep the triangles' orientation. Returns the number of quadrangles made.
// Triangles are never joined across an edge of `keptEdges` (edge keys of curve segments,
// sorted: see edgeKey).
enum class RecombinationAlgorithm { Simple = 0, Blossom = 1 };
std::size_t recombineTriangles(const Mesh& mesh, EntityMesh& em, RecombinationAlgorithm algorithm,
                               const std::vector<std::uint64_t>& keptEdges = {});

// How a surface is recombined, from the Mesh.Recombine* options.
struct RecombinationSettings {
  RecombinationAlgorithm algorithm = RecombinationAlgorithm::Blossom;
  double minQuality = 0.01;     // Mesh.RecombineMinimumQuality, by quadAngleQuality
  int topologyPasses = 5;       // Mesh.RecombineOptimizeTopology
  bool repositionNodes = true;  // Mesh.RecombineNodeRepositioning
  int smoothingPasses = 3;      // of the final smoothing
};

// The whole recombination of one surface's triangles: recombineTriangles; for Blossom, the
// leftover triangles paired (pairLeftoverTriangles) and up to `topologyPasses` passes of
// removeTwoQuadNodes and removeDiamonds, until one removes nothing; the quadrangles below
// `minQuality` cut back into triangles (splitPoorQuadrangles). When `repositionNodes`, the
// nodes are smoothed (smoothMixedMesh) by one pass after the pairing and after each clean-up
// pass, and by `smoothingPasses` at the end. Returns the number of quadrangles left.
std::size_t recombineSurface(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em,
                             const RecombinationSettings& settings,
                             const std::vector<std::uint64_t>& keptEdges = {});

// Cuts each quadrangle whose quadAngleQuality is below `minQuality` into two triangles, along
// the diagonal that gives the better shaped pair. Returns the number of quadrangles cut.
std::size_t splitPoorQuadrangles(const Mesh& mesh, EntityMesh& em, double minQuality);

// Topological clean-up of a recombined surface (Mesh.RecombineOptimizeTopology). A node of the
// surface's own held by exactly two quadrangles goes, the two becoming one (removeTwoQuadNodes);
// a quadrangle with two opposite corners of the surface's own each held by exactly three
// quadrangles collapses along that diagonal, the two corners merging at its middle on the
// surface (removeDiamonds). A change is kept only when the quadrangles it makes are convex.
// The removed nodes leave em.nodes (the mesh still holds them: see Mesh::dropUnheldNodes).
// Each returns the number of nodes removed.
// Drops the element blocks left empty and the nodes in `dropped` (with their parameters) from
// a surface's own, after a pass took elements and nodes out.
void dropOwnNodes(EntityMesh& em, const std::unordered_set<NodeIndex>& dropped);

std::size_t removeTwoQuadNodes(const Mesh& mesh, EntityMesh& em);
std::size_t removeDiamonds(const SurfaceGeometry& g, Mesh& mesh, EntityMesh& em);

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
