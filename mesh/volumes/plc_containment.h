// rejectEmbeddedOutside: each entity embedded in a volume checked, exactly, to lie inside it.
#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

// TetGen drops the points it finds outside the domain and renumbers the others, so what is
// embedded must lie inside the volume (within its outer shell, outside its holes). For a
// complex whose pieces do not cross each other (see rejectIntersections), one place on each
// embedded surface, curve and point tells: the parity of the shell triangles a ray from there
// crosses, by exact predicates. Throws MeshError naming the volume and the entity outside it.
void rejectEmbeddedOutside(const ModelVolume& volume, const VolumePlc& plc,
                           const std::vector<Vec3>& xyz);

}  // namespace geomesh
