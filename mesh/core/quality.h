// Element quality (gamma, SICN), mesh quality statistics, and element lengths, areas, volumes.
#pragma once

#include <cstddef>
#include <span>

#include "kernel/vec3.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// Element quality measures, 1 for the equilateral triangle / regular tetrahedron and 0 for a
// flat element.
//  gamma: inscribed over circumscribed radius, normalised (x2 for triangles, x3 for tets).
//  SICN:  signed inverse condition number of the Jacobian mapped to the regular element
//         (Frobenius norm); negative for an inverted element.
double triangleGamma(Vec3 a, Vec3 b, Vec3 c);
// Triangle SICN; the sign is that of the triangle's normal along `normal` (unsigned when
// normal is zero).
double triangleSicn(Vec3 a, Vec3 b, Vec3 c, Vec3 normal = {});
double tetGamma(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
double tetSicn(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

enum class QualityMeasure { Gamma, Sicn };

struct QualityStats {
  std::size_t count = 0;
  double min = 0, mean = 0;
};

// Statistics over all linear triangles (dim 2) or tetrahedra (dim 3) of the mesh; triangle
// SICN is unsigned here (a Mesh alone does not know which side of a surface is up).
QualityStats meshQuality(const Mesh& mesh, int dim, QualityMeasure measure);

// Length, area or volume of one first-order element (Line2, Triangle3, Quad4 split along its
// first diagonal, Tet4); 0 for other types.
double elementMeasure(const Mesh& mesh, ElementType type, std::span<const NodeIndex> nodes);

}  // namespace geomesh
