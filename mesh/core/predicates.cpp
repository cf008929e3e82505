// orient2d, incircle, orient3d and insphere: floating-point filters, then CGAL's exact ones.
#include "mesh/core/predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

namespace geomesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_2 toCgal(Vec2 p) {
  return {p.u, p.v};
}
Kernel::Point_3 toCgal(Vec3 p) {
  return {p.x, p.y, p.z};
}

// The 2D predicates first evaluate their determinant in doubles, with the sum of the absolute
// values of its terms (the permanent) alongside; a sign is trusted when the determinant
// exceeds the permanent times a bound well above the published worst-case relative errors of
// these evaluation orders (about 3.3e-16 and 1.1e-15 for orient2d and incircle). Otherwise
// CGAL's exact predicate decides. The 3D ones go to CGAL directly: its own semi-static filter
// (a bound from the largest coordinate differences) is cheaper than a permanent, and these
// two are the mesher's most frequent calls.
constexpr double kOrient2dBound = 1e-14;
constexpr double kIncircleBound = 1e-13;

// +1 or -1 when |det| is above bound * permanent, 0 when the filter cannot tell.
int filtered(double det, double permanent, double bound) {
  const double limit = bound * permanent;
  if (det > limit) return 1;
  if (-det > limit) return -1;
  return 0;
}

}  // namespace

int orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double bx = b.u - a.u, by = b.v - a.v, cx = c.u - a.u, cy = c.v - a.v;
  const double left = bx * cy, right = by * cx;
  if (const int sign = filtered(left - right, std::abs(left) + std::abs(right), kOrient2dBound))
    return sign;
  return static_cast<int>(Kernel::Orientation_2()(toCgal(a), toCgal(b), toCgal(c)));
}

int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double ax = a.u - d.u, ay = a.v - d.v, bx = b.u - d.u, by = b.v - d.v;
  const double cx = c.u - d.u, cy = c.v - d.v;
  const double bc = bx * cy - cx * by, ca = cx * ay - ax * cy, ab = ax * by - bx * ay;
  const double al = ax * ax + ay * ay, bl = bx * bx + by * by, cl = cx * cx + cy * cy;
  const double det = al * bc + bl * ca + cl * ab;
  const double permanent = al * (std::abs(bx * cy) + std::abs(cx * by)) +
                           bl * (std::abs(cx * ay) + std::abs(ax * cy)) +
                           cl * (std::abs(ax * by) + std::abs(bx * ay));
  if (const int sign = filtered(det, permanent, kIncircleBound)) return sign;
  return static_cast<int>(
      Kernel::Side_of_oriented_circle_2()(toCgal(a), toCgal(b), toCgal(c), toCgal(d)));
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return static_cast<int>(Kernel::Orientation_3()(toCgal(a), toCgal(b), toCgal(c), toCgal(d)));
}

int insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  return static_cast<int>(
      Kernel::Side_of_oriented_sphere_3()(toCgal(a), toCgal(b), toCgal(c), toCgal(d), toCgal(e)));
}

}  // namespace geomesh
