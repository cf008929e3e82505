// ExtrusionMotion: the motions of an extrusion's sweep: translation, rotation, twist, normals.
#pragma once

#include "kernel/vec3.h"

namespace geomesh {

// The sweep of an extrusion, as a family of rigid motions M_s, s in [0, 1] (M_0 = identity):
// a translation by s d, a rotation by s angle about an axis, or both at once (a twist).
// Normals is a boundary layer (Extrude without a vector): the geometry stays where it is and
// the mesh grows along the normals of the mesh of every source extruded with the same index
// (Using Index[i]); the heights of its Layers are lengths, not fractions. Using View[v] sets
// them apart per node: a scalar view scales the heights, a vector view replaces the unit
// normal (the node moves by height times the vector).
struct ExtrusionMotion {
  enum class Kind { Translation, Rotation, Twist, Normals };
  Kind kind = Kind::Translation;
  Vec3 translation;         // Translation, Twist
  Vec3 axis{0, 0, 1};       // Rotation, Twist: direction of the axis
  Vec3 axisPoint;           // a point of the axis
  double angle = 0;         // radians, right-hand rule about `axis`
  int layerIndex = 0;       // Normals: the i of Using Index[i]
  int layerView = -1;       // Normals: the v of Using View[v]; -1: none

  static ExtrusionMotion translate(Vec3 d) { return {Kind::Translation, d, {0, 0, 1}, {}, 0}; }
  static ExtrusionMotion rotate(Vec3 axis, Vec3 point, double angle) {
    return {Kind::Rotation, {}, axis, point, angle};
  }
  static ExtrusionMotion twist(Vec3 d, Vec3 axis, Vec3 point, double angle) {
    return {Kind::Twist, d, axis, point, angle};
  }
  static ExtrusionMotion normals(int index, int view = -1) {
    return {Kind::Normals, {}, {0, 0, 1}, {}, 0, index, view};
  }

  // M_s(p), and its derivatives with respect to s and (applied to a vector) to p.
  Vec3 apply(Vec3 p, double s) const;
  Vec3 velocity(Vec3 p, double s) const;
  Vec3 rotateVector(Vec3 v, double s) const;
};

}  // namespace geomesh
