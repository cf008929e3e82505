// anisotropicMesh: Mesh.Algorithm 7, triangles of unit edge length in a metric field.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/surfaces/frontal_refinement.h"
#include "mesh/surfaces/planar_mesh.h"
#include "mesh/surfaces/surface_metric.h"
#include "mesh/surfaces/triangulation2d.h"

namespace geomesh {

// The metric asked for at a work-plane point, in work-plane terms: a work-plane vector d has
// length sqrt(d' M d), the target being 1 for every edge. On a curved surface it includes the
// surface's own lengths (a 3D metric restricted through the surface's tangents).
using WorkPlaneMetric = std::function<Metric2(Vec2)>;

// Mesh.AnisoMax and Mesh.SmoothRatio.
struct AnisotropicSettings {
  double anisoMax = 1e33;    // largest ratio of the two sizes of a metric
  double smoothRatio = 1.8;  // largest growth of sizes per unit of metric length; <= 1: none
};

// Anisotropic meshing (the reference's BAMG slot) by metric-driven local modifications of the
// constrained Delaunay triangulation of the boundary: passes of edge splits at the middle
// (edges longer than sqrt 2 in the metric), collapses (shorter than 1/sqrt 2; boundary and
// embedded vertices stay), swaps that raise the worse metric quality of two triangles, and
// smoothing towards unit lengths, until every free edge is within range or the passes stop
// making progress (40 at most). No triangle is ever inverted in the work plane (exact
// orientation tests). Each pass costs O(n log n).
//
// The metric at a vertex is `metric` there, intersected with the isotropic `bound` when given.
// With no metric, sizes are unbounded inside, and boundary and embedded vertices (below
// `firstMovable`) ask for the isotropic size of the boundary (Triangulation2D::size). Sizes are clamped to the domain's
// extent and to settings.anisoMax, then graded by settings.smoothRatio along the mesh's
// edges: so without a metric, sizes grow from the boundary's inwards at that rate.
// `surface` (null on planes) gives the surface's lengths for the isotropic sizes.
PlanarMesh anisotropicMesh(const Triangulation2D& boundary, const std::vector<std::uint8_t>& inside,
                           std::uint32_t firstMovable, int smoothingPasses,
                           const SurfaceMetric* surface, const WorkPlaneMetric* metric,
                           const WorkPlaneSize* bound, const AnisotropicSettings& settings);

}  // namespace geomesh
