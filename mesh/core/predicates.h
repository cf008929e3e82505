// Exact orientation and in-circle/in-sphere predicates behind every meshing decision.
#pragma once

#include "kernel/vec3.h"

namespace geomesh {

// Robust geometric predicates: the sign of each answer is exact for any double input (CGAL's
// filtered exact predicates behind a plain interface). Every combinatorial decision of the
// meshers goes through these functions. The 3D ones take references: a Vec3 by value is
// copied to the stack at each of their millions of calls.

// +1 if a, b, c turn counter-clockwise, -1 if clockwise, 0 if collinear.
int orient2d(Vec2 a, Vec2 b, Vec2 c);
// For a, b, c counter-clockwise: +1 if d lies inside their circumcircle, -1 outside, 0 on it.
int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
// +1 if d lies on the positive side of the plane through a, b, c (a, b, c counter-clockwise
// seen from d), -1 on the other side, 0 if coplanar.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// For a positively oriented tetrahedron a, b, c, d (orient3d(a, b, c, d) > 0): +1 if e lies
// inside its circumsphere, -1 outside, 0 on it.
int insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e);

}  // namespace geomesh
