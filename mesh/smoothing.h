#pragma once

#include <cstdint>
#include <vector>

#include "mesh/delaunay2d.h"
#include "mesh/surface_metric.h"

namespace geomesh {

// Laplacian smoothing of the vertices numbered from `firstMovable` on: each moves to the mean
// of its neighbours unless that would invert or flatten one of its triangles. After each pass
// free edges are flipped back to (constrained) Delaunay, judged in the surface's metric at
// each edge when a metric is given. Only triangles flagged in `inside` are considered.
void smoothTriangulation(Triangulation2D& tri, const std::vector<std::uint8_t>& inside,
                         std::uint32_t firstMovable, int passes,
                         const SurfaceMetric* metric = nullptr);

}  // namespace geomesh
