// Frontal-Delaunay refinement (Rebay), its quadrangle variant, and Delaunay refinement in 2D.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/surfaces/delaunay2d.h"
#include "mesh/surfaces/surface_metric.h"

namespace geomesh {

using WorkPlaneSize = std::function<double(Vec2)>;

// Frontal-Delaunay refinement (after Rebay, J. Comput. Phys. 106, 1993) of a constrained
// Delaunay triangulation. Triangles whose circumradius fits the target size are accepted; the
// others that touch the front (a constrained edge or an accepted triangle) get a new point
// on the perpendicular bisector of their front edge, placed to make a near-equilateral
// triangle of the target size, and inserted by Bowyer-Watson. Larger triangles go first.
//
// `inside` flags the triangles of the domain (classifyInside) and grows with the
// triangulation, which holds the target size at each vertex (Triangulation2D::size). New
// points get the size interpolated linearly from the triangle they fall in, so sizes extend
// from the boundary inwards.
// With a metric (curved surfaces), lengths, circumradii and point placement are measured on
// the surface rather than in the work plane.
// With `field` (a background size field, given at work-plane points), the target size of a
// triangle or an edge is the smaller of the means, over its vertices, of the interpolated sizes
// and of the field's: the field is seen at vertices only, as the reference sees it, so a zone
// of much smaller sizes between vertices is only refined once a vertex falls in it. `bound`
// (sizes that must hold for the mesh to be valid, such as a few elements per turn of a tight
// bend) is seen wherever a size is used: at a triangle's centroid, an edge's midpoint.
void refineFrontal(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                   const SurfaceMetric* metric = nullptr,
                   const WorkPlaneSize* field = nullptr, const WorkPlaneSize* bound = nullptr);

// Frontal-Delaunay for quadrangles (Mesh.Algorithm 8): the same front, but the ideal
// triangle is the right isosceles one with legs of the target size, placed along a cross
// field taken from the directions of the constrained edges, so that pairs of triangles
// make square cells for recombination.
void refineFrontalQuads(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                        const SurfaceMetric* metric = nullptr,
                        const WorkPlaneSize* field = nullptr,
                        const WorkPlaneSize* bound = nullptr);

// Delaunay refinement (Mesh.Algorithm 5): the same acceptance test, but every bad triangle
// is refined, worst first, by inserting its circumcentre (in the surface's metric), or its
// centroid when the circumcentre lies outside the domain.
void refineDelaunay(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                    const SurfaceMetric* metric = nullptr,
                    const WorkPlaneSize* field = nullptr, const WorkPlaneSize* bound = nullptr);

}  // namespace geomesh
