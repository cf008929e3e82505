// rejectEmbeddedOutside: each entity embedded in a volume checked, exactly, to lie inside it.
#pragma once

#include <optional>
#include <vector>

#include "kernel/model.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

// TetGen drops the points it finds outside the domain and renumbers the others, so what is
// embedded must lie inside the volume (within its outer shell, outside its holes). For a
// complex whose pieces do not cross each other (see rejectIntersections), one place on each
// embedded surface, curve and point tells: the parity of the shell triangles a ray from there
// crosses, by exact predicates. Throws MeshError naming the volume and the entity outside it.
// Whether p lies inside the shells (triangles [0, plc.shellEnd)), which `shells` bounds: an
// odd number of their triangles crossed on a ray out, by exact predicates; nullopt when every
// ray tried grazes a triangle.
std::optional<bool> insideShells(Vec3 p, const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                 const BoundingBox& shells);

void rejectEmbeddedOutside(const ModelVolume& volume, const VolumePlc& plc,
                           const std::vector<Vec3>& xyz);

}  // namespace geomesh
