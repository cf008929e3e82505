// orient2d, incircle, orient3d and insphere: a floating-point filter, then CGAL's exact ones.
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

// Each predicate first evaluates its determinant in doubles, with the sum of the absolute
// values of its terms (the permanent) alongside; a sign is trusted when the determinant
// exceeds the permanent times a bound well above the published worst-case relative errors of
// these evaluation orders (about 3.3e-16, 1.1e-15, 7.8e-16 and 1.8e-15 for orient2d,
// incircle, orient3d and insphere). Otherwise CGAL's exact predicate decides.
constexpr double kOrient2dBound = 1e-14;
constexpr double kIncircleBound = 1e-13;
constexpr double kOrient3dBound = 1e-14;
constexpr double kInsphereBound = 1e-13;

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

int orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  const double m1 = cy * dz, m2 = cz * dy, m3 = cz * dx, m4 = cx * dz, m5 = cx * dy, m6 = cy * dx;
  const double det = bx * (m1 - m2) + by * (m3 - m4) + bz * (m5 - m6);
  const double permanent = std::abs(bx) * (std::abs(m1) + std::abs(m2)) +
                           std::abs(by) * (std::abs(m3) + std::abs(m4)) +
                           std::abs(bz) * (std::abs(m5) + std::abs(m6));
  if (const int sign = filtered(det, permanent, kOrient3dBound)) return sign;
  return static_cast<int>(Kernel::Orientation_3()(toCgal(a), toCgal(b), toCgal(c), toCgal(d)));
}

int insphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  const double ax = a.x - e.x, ay = a.y - e.y, az = a.z - e.z;
  const double bx = b.x - e.x, by = b.y - e.y, bz = b.z - e.z;
  const double cx = c.x - e.x, cy = c.y - e.y, cz = c.z - e.z;
  const double dx = d.x - e.x, dy = d.y - e.y, dz = d.z - e.z;
  // 2x2 minors of the x and y columns, then 3x3 minors with z, then the lifted column.
  const double ab = ax * by - bx * ay, bc = bx * cy - cx * by, cd = cx * dy - dx * cy;
  const double da = dx * ay - ax * dy, ac = ax * cy - cx * ay, bd = bx * dy - dx * by;
  const double abc = az * bc - bz * ac + cz * ab;
  const double bcd = bz * cd - cz * bd + dz * bc;
  const double cda = cz * da + dz * ac + az * cd;
  const double dab = dz * ab + az * bd + bz * da;
  const double al = ax * ax + ay * ay + az * az, bl = bx * bx + by * by + bz * bz;
  const double cl = cx * cx + cy * cy + cz * cz, dl = dx * dx + dy * dy + dz * dz;
  const double det = (dl * abc - cl * dab) + (bl * cda - al * bcd);
  auto p2 = [](double x1, double y1, double x2, double y2) {
    return std::abs(x1 * y2) + std::abs(x2 * y1);
  };
  const double pab = p2(ax, ay, bx, by), pbc = p2(bx, by, cx, cy), pcd = p2(cx, cy, dx, dy);
  const double pda = p2(dx, dy, ax, ay), pac = p2(ax, ay, cx, cy), pbd = p2(bx, by, dx, dy);
  const double permanent =
      dl * (std::abs(az) * pbc + std::abs(bz) * pac + std::abs(cz) * pab) +
      cl * (std::abs(dz) * pab + std::abs(az) * pbd + std::abs(bz) * pda) +
      bl * (std::abs(cz) * pda + std::abs(dz) * pac + std::abs(az) * pcd) +
      al * (std::abs(bz) * pcd + std::abs(cz) * pbd + std::abs(dz) * pbc);
  // The determinant is negative when e lies inside the sphere of a positive tetrahedron.
  if (const int sign = filtered(det, permanent, kInsphereBound)) return -sign;
  return static_cast<int>(
      Kernel::Side_of_oriented_sphere_3()(toCgal(a), toCgal(b), toCgal(c), toCgal(d), toCgal(e)));
}

}  // namespace geomesh
