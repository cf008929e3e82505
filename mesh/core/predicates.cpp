// orient2d, incircle, orient3d and insphere over CGAL's filtered exact predicates.
#include "mesh/core/predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace geomesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_2 toCgal(Vec2 p) {
  return {p.u, p.v};
}
Kernel::Point_3 toCgal(Vec3 p) {
  return {p.x, p.y, p.z};
}

}  // namespace

int orient2d(Vec2 a, Vec2 b, Vec2 c) {
  return static_cast<int>(Kernel::Orientation_2()(toCgal(a), toCgal(b), toCgal(c)));
}

int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return static_cast<int>(
      Kernel::Side_of_oriented_circle_2()(toCgal(a), toCgal(b), toCgal(c), toCgal(d)));
}

int orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return static_cast<int>(Kernel::Orientation_3()(toCgal(a), toCgal(b), toCgal(c), toCgal(d)));
}

int insphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  return static_cast<int>(
      Kernel::Side_of_oriented_sphere_3()(toCgal(a), toCgal(b), toCgal(c), toCgal(d), toCgal(e)));
}

}  // namespace geomesh
