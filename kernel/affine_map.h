// AffineMap: a 3 x 4 affine transformation about a pivot, for transforms and periodicity.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "kernel/vec3.h"

namespace geomesh {

// x -> A (x - pivot) + b + pivot, A and b stored as the 3 x 4 row-major matrix [A | b]
// (Affine{..} in scripts takes these 12 numbers; its pivot is the origin). Rotations keep
// their center as the pivot: moving to it, turning, and moving back as three steps rounds as
// the built-in kernel of Gmsh does (to the last digit in most cases).
struct AffineMap {
  std::array<double, 12> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  Vec3 pivot{};

  Vec3 apply(Vec3 p) const {
    const Vec3 q = p - pivot;
    const Vec3 r{m[0] * q.x + m[1] * q.y + m[2] * q.z + m[3],
                 m[4] * q.x + m[5] * q.y + m[6] * q.z + m[7],
                 m[8] * q.x + m[9] * q.y + m[10] * q.z + m[11]};
    return r + pivot;
  }

  static AffineMap translation(Vec3 d);
  // By `angle` radians about the axis through `point` along `axis` (right-hand rule).
  static AffineMap rotation(Vec3 axis, Vec3 point, double angle);
  // Mirror image through the plane a x + b y + c z + d = 0.
  static AffineMap symmetry(double a, double b, double c, double d);
  // Scaling about `center` by factors per axis.
  static AffineMap dilation(Vec3 center, Vec3 factors);
  // The same map as a 4 x 4 row-major matrix (pivot folded in), for periodicity records.
  std::array<double, 16> homogeneous() const;
};

// The rigid motion taking each pair's first point onto its second, or nullopt when there is
// none (within `tolerance`): a translation when all the displacements agree, else the motion
// fixed by three pairs far from collinear, checked on all of them. (The older form of Periodic
// Surface, in both kernels.)
std::optional<AffineMap> rigidMotion(const std::vector<std::pair<Vec3, Vec3>>& pairs,
                                     double tolerance);

}  // namespace geomesh
