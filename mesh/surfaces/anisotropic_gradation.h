// gradeMetrics: bounds how fast metric sizes grow from vertex to vertex (Mesh.SmoothRatio).
#pragma once

#include <cstdint>
#include <span>

#include "kernel/vec3.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {

// The vertices' neighbours in compressed rows: those of v are
// neighbours[offsets[v] .. offsets[v + 1]).
struct VertexGraph {
  std::span<const std::uint32_t> offsets;
  std::span<const std::uint32_t> neighbours;
};

// Metric gradation (after Alauzet, "Size gradation control of anisotropic meshes", 2010):
// lowers the metrics until, for every edge (a, b), M_b is no larger a size in any direction
// than M_a grown along the edge, M_a / (1 + l (ratio - 1))^2 with l the edge's length under
// M_a: sizes grow by at most `ratio` along an edge of unit length (Mesh.SmoothRatio, "the
// ratio between the sizes at the nodes of an edge"), linearly with the Euclidean distance
// from a vertex. Sizes only go down. Vertices are settled smallest size first, as in Dijkstra's
// algorithm, so each is revisited only when a neighbour lowers it by more than a percent:
// O(n log n) for n vertices. No change when ratio <= 1 or is not finite.
void gradeMetrics(std::span<const Vec2> points, VertexGraph graph, std::span<Metric2> metrics,
                  double ratio);

}  // namespace geomesh
