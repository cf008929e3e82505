// adaptMesh: MeshAdapt (Mesh.Algorithm 1), meshing by local modifications of a triangulation.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/surfaces/delaunay2d.h"
#include "mesh/surfaces/frontal_refinement.h"
#include "mesh/surfaces/planar_mesh.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {

// MeshAdapt (Mesh.Algorithm 1): meshing by local modifications of the constrained Delaunay
// triangulation of the boundary. Passes of edge splits (edges longer than 1.4 target sizes),
// collapses (shorter than 0.7), quality-improving swaps and smoothing repeat until every free edge
// is within range or, once no edge is more than twice too long, three passes in a row fail to
// reduce the number of edges out of range (40 passes at most). Each pass costs O(n log n) in the
// number of edges.
//
// `boundary` is the constrained triangulation with the triangles of the domain flagged in `inside`,
// and the target size at its vertices (Triangulation2D::size). Vertices from `firstMovable` on may
// move or disappear; the others (boundary and embedded nodes) and the non-free edges stay as they
// are. Target sizes inside are interpolated linearly over the boundary triangulation (extended from
// the boundary), capped by `field` when one is given. With a metric, lengths and qualities are
// measured on the surface. `smoothingPasses` adds that many final passes of smoothing and swaps.
PlanarMesh adaptMesh(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
                     std::uint32_t firstMovable, int smoothingPasses,
                     const SurfaceMetric* metric = nullptr,
                     const WorkPlaneSize* field = nullptr);

}  // namespace geomesh
