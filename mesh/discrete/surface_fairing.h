// fair: smoothing of a noisy merged triangulation (scan, STL) by mean-curvature flow.
#pragma once

#include "mesh/discrete/triangulation.h"

namespace geomesh {

// step: the time step of each iteration, in units of the squared mean edge length.
struct FairingOptions {
  int iterations = 10;
  double step = 0.5;
  bool keepBoundary = true;
};

// Smooths a noisy surface: iterations of implicit mean-curvature flow (Desbrun, Meyer, Schröder,
// Barr 1999) with the cotangent Laplacian of the current surface and lumped (barycentric)
// areas, the vertices of boundary and non-manifold edges fixed when keepBoundary; a closed
// surface (every edge shared by two triangles) is rescaled about its vertices' centroid after
// each iteration to keep its enclosed volume. In place.
void fair(Triangulation& t, const FairingOptions& options);

}  // namespace geomesh
