// addPyramids: the quadrangles of a volume's boundary become the bases of pyramids.
#pragma once

#include <array>
#include <vector>

#include "mesh/core/mesh.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

using Pyramid = std::array<int, 5>;  // local nodes: base counter-clockwise seen from the apex, apex

// A tetrahedron cannot have a quadrangle as a face, so where a tetrahedral volume meets a
// recombined or layered surface, each quadrangle of that surface gets a pyramid standing on
// it inside the volume (as the reference meshes such volumes).

// Per quadrangle of plc.quads, its unit normal pointing into the volume: the side is told by
// an exact parity test against the whole boundary, once per surface (a surface's elements
// all face along its normal). Throws MeshError naming volume `volumeTag` when a surface's
// sides cannot be told apart (both or neither inside the volume).
std::vector<Vec3> inwardNormals(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                int volumeTag);

// Stands the pyramids: each apex, a new node of the complex, lies `height` times its
// quadrangle's mean edge length from the quadrangle's centre along `inward`; the complex then
// has the pyramid's four side triangles in the quadrangle's place, in the same shell, and the
// tetrahedra fill what the pyramids leave. Clears plc.quads and extends `xyz`; the apexes'
// entries of plc.nodes are kNoNode, for the caller to make mesh nodes of.
inline constexpr NodeIndex kNoNode = ~NodeIndex{0};
std::vector<Pyramid> addPyramids(VolumePlc& plc, std::vector<Vec3>& xyz,
                                 const std::vector<Vec3>& inward, double height);

}  // namespace geomesh
