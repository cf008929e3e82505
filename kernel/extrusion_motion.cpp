// ExtrusionMotion: points, velocities and turned vectors along a translation, rotation, twist.
#include "kernel/extrusion_motion.h"

#include <cmath>

#include "kernel/affine_map.h"

namespace geomesh {

namespace {

// v turned by `angle` about the unit vector u (Rodrigues' formula).
Vec3 turn(Vec3 v, Vec3 u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * cross(u, v) + (1 - c) * dot(u, v) * u;
}

}  // namespace

Vec3 ExtrusionMotion::rotateVector(Vec3 v, double s) const {
  if (kind == Kind::Translation || kind == Kind::Normals) return v;
  return turn(v, normalized(axis), s * angle);
}

// Points turn by the matrix of AffineMap::rotation, so that they round as transformed points.
Vec3 ExtrusionMotion::apply(Vec3 p, double s) const {
  if (kind == Kind::Normals) return p;  // the mesh moves, along normals only it knows
  if (kind == Kind::Translation) return p + s * translation;
  const Vec3 turned = AffineMap::rotation(axis, axisPoint, s * angle).apply(p);
  return kind == Kind::Twist ? turned + s * translation : turned;
}

Vec3 ExtrusionMotion::velocity(Vec3 p, double s) const {
  if (kind == Kind::Normals) return {};
  if (kind == Kind::Translation) return translation;
  const Vec3 u = normalized(axis);
  const Vec3 spin = angle * cross(u, rotateVector(p - axisPoint, s));
  return kind == Kind::Twist ? spin + translation : spin;
}

}  // namespace geomesh
