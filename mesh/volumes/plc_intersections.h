// rejectIntersections: a volume's complex checked, exactly, for pieces that cross each other.
#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

// TetGen 1.5 crashes (it releases its memory twice) when it gives up on an input, typically a
// boundary whose triangles cross each other, so such inputs are detected first, exactly: two
// pieces of the complex (triangles, segments, points) may only share the corners or the edge
// they have in common. Throws MeshError naming the volume and the two entities (the boundary
// intersecting itself, or an embedded surface, curve or point crossing or lying on the
// boundary or another embedded entity), near where they meet.
void rejectIntersections(const ModelVolume& volume, const VolumePlc& plc,
                         const std::vector<Vec3>& xyz);

}  // namespace geomesh
