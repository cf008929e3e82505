// Validity and size of curved elements: bounds of the Jacobian determinant over the reference
// element, the scaled Jacobian, and the measure (length, area, volume) of an element.
#pragma once

#include <array>
#include <span>

#include "kernel/vec3.h"
#include "mesh/core/element_type.h"

namespace geomesh {

// Bounds of the Jacobian determinant over the whole reference element. An element is valid
// iff min > 0: `min` is a lower bound, refined until it decides that sign (or, for an element
// whose determinant barely touches zero, left <= 0 when refining costs too much).
struct JacobianRange {
  double min = 0, max = 0;
};

// The determinant at reference point xi of the element of `type` whose nodes (MSH order)
// are `nodes`: for volume elements det(dx/dxi); for surface elements (x_u x x_v) . n, with n
// the unit normal of the plane of the first three vertices; for lines dx/du . t, with t the
// unit vector from the first vertex to the second. 1 for points.
double jacobianDeterminant(ElementType type, std::span<const Vec3> nodes,
                           const std::array<double, 3>& xi);

// Whether every node lies where the first-order element of the corners puts it (within 1e-12
// of the element's size): the element is then not curved.
bool isStraight(ElementType type, std::span<const Vec3> nodes);

// Bounds from Bernstein (Bezier) coefficients of the determinant, a polynomial, refined by
// subdividing the reference element where the bound alone cannot tell the sign. Pyramids
// are sampled on a dense lattice instead (see jacobian.cpp). A straight simplex has the
// constant determinant of its corners, found without a search.
JacobianRange jacobianRange(ElementType type, std::span<const Vec3> nodes);

// min / max of the determinant (min / max(|min|, |max|)): in (0, 1] for a valid element, 1
// for a straight simplex, <= 0 for an invalid one.
double scaledJacobian(ElementType type, std::span<const Vec3> nodes);

// Length, area or volume of a possibly curved element, by Gauss quadrature of |det J| (of
// sqrt(det(J^T J)) for lines and surfaces); 0 for points.
double elementMeasure(ElementType type, std::span<const Vec3> nodes);

}  // namespace geomesh
