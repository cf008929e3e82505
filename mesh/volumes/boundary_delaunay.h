// boundaryDelaunay: a volume's boundary-conforming tetrahedra straight from the Delaunay kernel.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/volumes/delaunay_tets.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

// The Delaunay tetrahedralization of the complex's nodes, when it already holds every triangle
// and segment of the complex (as for most well-shaped surface meshes): the tetrahedra outside
// the outer shell, or inside a hole (a closed inner shell holding one of `holes`), are
// removed, and the triangles of embedded surfaces are kept. Empty when a piece of the complex
// is missing or the tetrahedra left are not bounded by the shells exactly; the boundary is
// then recovered otherwise (TetGen).
std::optional<DelaunayTets> boundaryDelaunay(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                             const std::vector<Vec3>& holes);

// The kernel's mesh of tetrahedra (4 indices into `points` each, positive) that hold the
// complex: the embedded surfaces' triangles become kept faces, the segments kept edges.
DelaunayTets complexTetrahedra(const VolumePlc& plc, std::vector<Vec3> points,
                               std::vector<std::uint32_t> tets);

}  // namespace geomesh
