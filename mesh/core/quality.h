// Element quality (gamma, SICN), mesh quality statistics, and element lengths, areas, volumes.
#pragma once

#include <cmath>
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
// The cube of a tetrahedron's mean ratio 12 (3V)^(2/3) / (sum of squared edge lengths), with
// the sign of its volume: 1 for the regular tetrahedron, 0 when flat. It orders tetrahedra as
// the mean ratio does and costs no root, for optimizers' comparisons. Inline: the smoother and
// the optimizer call it millions of times.
inline double tetMeanRatioCubed(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double volume6 = dot(u, cross(v, w));
  const double edges = dot(u, u) + dot(v, v) + dot(w, w) + dot(c - b, c - b) +
                       dot(d - b, d - b) + dot(d - c, d - c);
  if (!(edges > 0)) return 0;
  // (12 (3V)^(2/3) / S)^3 = 15552 V^2 / S^3, with V = volume6 / 6.
  return 432 * volume6 * std::abs(volume6) / (edges * edges * edges);
}
// Above this, tetMeanRatioCubed's sign (that of a volume computed in doubles) is certainly the
// tetrahedron's orientation: rounding moves it by some 1e-15 of its terms.
inline constexpr double kSureMeanRatioCubed = 1e-6;
double tetSicn(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// The scaled Jacobian at the corners of a first-order element (its first vertexCount nodes):
// the smallest over its corners of the triple product (in 2D, the cross product along the
// element's normal) of the unit edge vectors leaving the corner, scaled so that the ideal
// element (equilateral triangle or tetrahedron, square, right prism over an equilateral
// triangle, cube) has 1, and capped at 1. Negative at an inverted corner; 1 for points and
// lines. Pyramids: the four corners of the base.
double cornerScaledJacobian(ElementType type, std::span<const Vec3> nodes);

enum class QualityMeasure { Gamma, Sicn };

// The quality of the first-order element of an element's corners (its first vertexCount nodes,
// in `corners`): gamma or SICN for triangles (SICN unsigned) and tetrahedra, the corner scaled
// Jacobian for the other families, whichever the measure.
double elementQuality(ElementType type, std::span<const Vec3> corners, QualityMeasure measure);

struct QualityStats {
  std::size_t count = 0;
  double min = 0, mean = 0;
};

// Statistics over all triangles (dim 2) or tetrahedra (dim 3) of the mesh, of any order, each
// measured as the first-order element of its corners; triangle SICN is unsigned here (a Mesh
// alone does not know which side of a surface is up).
QualityStats meshQuality(const Mesh& mesh, int dim, QualityMeasure measure);

// Length, area or volume of the first-order element of an element's corners (its first
// vertexCount nodes), whatever its order: lines, triangles, quadrangles split along their first
// diagonal, tetrahedra, prisms, pyramids and hexahedra (cut into tetrahedra); 0 for points.
double elementMeasure(const Mesh& mesh, ElementType type, std::span<const NodeIndex> nodes);

}  // namespace geomesh
