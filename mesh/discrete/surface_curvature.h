// Vertex normals and discrete curvatures of a triangulated surface (scans, STL).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/discrete/triangulation.h"

namespace geomesh {

// Angle-weighted vertex normals (unit), per vertex of t; zero on vertices no triangle uses.
std::vector<Vec3> vertexNormals(const Triangulation& t);

struct VertexCurvatures {
  // Signed mean curvature H (positive on a sphere with outward normals: H = 1/R).
  std::vector<double> mean;
  std::vector<double> gaussian;  // K (1/R^2 on a sphere)
  // The largest principal curvature magnitude |H| + sqrt(max(0, H^2 - K)).
  std::vector<double> maxAbs;
};

// Discrete curvatures by the cotangent formula over mixed Voronoi areas (Meyer, Desbrun,
// Schröder, Barr 2003); on boundary vertices (of boundary or non-manifold edges) the average of
// the closest interior vertices' values, by edge hops, is used (or 0 when there is none).
VertexCurvatures vertexCurvatures(const Triangulation& t);

// The cotangents of the angles at the three corners of a triangle (0 for a degenerate one).
std::array<double, 3> cornerCotangents(const Triangulation& t, std::uint32_t triangle);

}  // namespace geomesh
