// smoothTriangulation: guarded Laplacian smoothing and Delaunay flips in the surface metric.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/surfaces/delaunay2d.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {

// What a smoothing move must keep: its triangles valid, or also the worst of their qualities
// (gamma, in the surface's metric) no lower, which leaves well-shaped patches as they are.
enum class SmoothingGuard { Validity, WorstQuality };

// Laplacian smoothing of the vertices numbered from `firstMovable` on: each moves to the mean
// of its neighbours unless that would invert or flatten one of its triangles (or, guarding
// quality, worsen the worst of them: then half and a quarter of the way are tried). After
// each pass free edges are flipped back to (constrained) Delaunay, judged in the surface's
// metric at each edge when a metric is given. Only triangles flagged in `inside` are
// considered.
void smoothTriangulation(Triangulation2D& tri, const std::vector<std::uint8_t>& inside,
                         std::uint32_t firstMovable, int passes,
                         const SurfaceMetric* metric = nullptr,
                         SmoothingGuard guard = SmoothingGuard::Validity);

}  // namespace geomesh
