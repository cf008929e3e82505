// rejectEmbeddedOutside: ray parity against the shells' triangles, rays that graze re-aimed.
#include "mesh/volumes/plc_containment.h"

#include <algorithm>
#include <optional>
#include <string>

#include "mesh/core/mesh_error.h"
#include "mesh/core/predicates.h"

namespace geomesh {

namespace {

// Directions of no special alignment with the axes or with each other.
constexpr Vec3 kRays[] = {{1, 0.3718, 0.1523},
                          {-0.2871, 1, 0.4419},
                          {0.3347, -0.1189, 1},
                          {-1, -0.5153, 0.2764},
                          {0.1731, -1, -0.6327}};

enum class Crossing { None, Through, Grazing };

// How the segment from p to q meets triangle t: not at all, through its inside, or at its
// border (an edge or a corner), which leaves the parity undecided. p on t grazes too.
Crossing segmentCrossing(Vec3 p, Vec3 q, const Vec3 t[3]) {
  const int sp = orient3d(t[0], t[1], t[2], p), sq = orient3d(t[0], t[1], t[2], q);
  if (sp == 0) {
    if (sq == 0) return Crossing::Grazing;  // along the plane, or a degenerate triangle
    // The line through p and q meets the plane at p only.
    const int a = orient3d(p, q, t[0], t[1]), b = orient3d(p, q, t[1], t[2]);
    const int c = orient3d(p, q, t[2], t[0]);
    return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0) ? Crossing::Grazing
                                                                        : Crossing::None;
  }
  if (sp * sq >= 0) return Crossing::None;  // q lies beyond every triangle: never on one
  const int a = orient3d(p, q, t[0], t[1]), b = orient3d(p, q, t[1], t[2]);
  const int c = orient3d(p, q, t[2], t[0]);
  if ((a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0)) return Crossing::Through;
  if ((a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0)) return Crossing::Grazing;
  return Crossing::None;
}

bool boxesOverlap(const BoundingBox& a, const BoundingBox& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
         a.min.z <= b.max.z && b.min.z <= a.max.z;
}

}  // namespace

std::optional<bool> insideShells(Vec3 p, const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                 const BoundingBox& shells) {
  const double reach = 2 * distance(shells.min, shells.max) + distance(p, shells.min);
  for (Vec3 direction : kRays) {
    const Vec3 q = p + reach * direction;
    BoundingBox ray;
    ray.include(p);
    ray.include(q);
    bool inside = false, grazed = false;
    for (std::size_t i = 0; i < plc.shellEnd && !grazed; ++i) {
      const Vec3 t[3] = {xyz[plc.triangles[i][0]], xyz[plc.triangles[i][1]],
                         xyz[plc.triangles[i][2]]};
      BoundingBox box;
      for (Vec3 c : t) box.include(c);
      if (!boxesOverlap(box, ray)) continue;
      const Crossing crossing = segmentCrossing(p, q, t);
      inside ^= crossing == Crossing::Through;
      grazed = crossing == Crossing::Grazing;
    }
    if (!grazed) return inside;
  }
  return std::nullopt;
}

namespace {

std::string near(Vec3 p) {
  return " (near (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
         std::to_string(p.z) + "))";
}

}  // namespace

void rejectEmbeddedOutside(const ModelVolume& volume, const VolumePlc& plc,
                           const std::vector<Vec3>& xyz) {
  BoundingBox shells;
  for (std::size_t i = 0; i < plc.shellEnd; ++i)
    for (int k : plc.triangles[i]) shells.include(xyz[k]);
  auto require = [&](Vec3 at, const std::string& what) {
    if (insideShells(at, plc, xyz, shells) == false)
      throw MeshError({3, volume.tag}, what + " lies outside the volume" + near(at));
  };
  // The first triangle or segment of each entity: its middle is off the shells even when its
  // corners are on them.
  for (std::size_t i = plc.shellEnd; i < plc.triangles.size(); ++i)
    if (i == plc.shellEnd || plc.surfaceOf[i] != plc.surfaceOf[i - 1]) {
      const PlcTriangle& t = plc.triangles[i];
      require((xyz[t[0]] + xyz[t[1]] + xyz[t[2]]) / 3,
              "embedded surface " + std::to_string(plc.surfaceOf[i]));
    }
  for (std::size_t i = 0; i < plc.segments.size(); ++i)
    if (i == 0 || plc.curveOf[i] != plc.curveOf[i - 1])
      require((xyz[plc.segments[i][0]] + xyz[plc.segments[i][1]]) / 2,
              "embedded curve " + std::to_string(plc.curveOf[i]));
  for (std::size_t i = 0; i < plc.points.size(); ++i)
    require(xyz[plc.points[i]], "embedded point " + std::to_string(plc.pointOf[i]));
}

}  // namespace geomesh
