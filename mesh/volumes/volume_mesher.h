// meshVolume: the tetrahedral mesh of one volume, boundary triangles kept; planned apart.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"
#include "mesh/volumes/pyramid_bases.h"
#include "mesh/volumes/volume_plc.h"

namespace geomesh {

// The size asked for at a point inside a volume.
using InteriorSize = std::function<double(Vec3)>;

// Meshes one volume with tetrahedra, from the triangle meshes of the surfaces of its shells,
// which `mesh` must hold already. The boundary triangles are kept exactly (no node is added on
// the boundary); interior nodes are added to the volume's EntityMesh and sized from the
// boundary edge lengths, bounded by options.sizeMin/sizeMax. Inner shells are holes. The
// entities embedded in the volume are kept exactly too: each triangle of an embedded surface is
// a face of two tetrahedra, one each side, each segment of an embedded curve an edge, each
// embedded point a node; the embedded surfaces' sizes spread into the volume as the boundary's
// do, while embedded curves and points, as in the reference, take the size of the nearest
// surface node. Quadrangles of the shells carry pyramids. The Tet4 elements are positively
// oriented. With `interiorSize` (the background field's size at a point, or null), the
// tetrahedra follow it inside too (bounded by the boundary's sizes when
// options.sizeExtendFromBoundary). Throws MeshError naming the volume on failure (missing or
// non-triangular surface mesh, intersecting boundary, an embedded entity crossing the boundary
// or another one, or lying outside the volume, a boundary that cannot be recovered, a mesh too
// large for the machine). The same as commitVolumeMesh(planVolumeMesh(...)).
void meshVolume(const Model& model, const MeshOptions& options, int volumeTag,
                const InteriorSize& interiorSize, Mesh& mesh);

// A volume's mesh made but not yet in the mesh: the complex (the pyramids' apexes are nodes
// still to add, kNoNode), every vertex's place (the complex's nodes first), the tetrahedra
// (4 vertices each) and the pyramids. Empty for a layered extrusion.
struct VolumeMeshing {
  int volume = 0;
  VolumePlc plc;
  std::vector<Vec3> points;
  std::vector<std::uint32_t> tets;
  std::vector<Pyramid> pyramids;
};

// How far the planning of one volume has come, from 0 to 1 (about: refinement is measured
// against the estimate of its tetrahedra).
using VolumeProgress = std::function<void(double fraction)>;

// The first half of meshVolume: reads `mesh` only, so that several volumes may be planned at
// once (`interiorSize` and `progress` must then be safe to call from several threads).
VolumeMeshing planVolumeMesh(const Model& model, const MeshOptions& options, int volumeTag,
                             const InteriorSize& interiorSize, const Mesh& mesh,
                             const VolumeProgress& progress = {});

// The second half: adds the planned nodes, tetrahedra and pyramids to the volume's mesh, then
// checks that the embedded entities are kept.
void commitVolumeMesh(const Model& model, VolumeMeshing&& planned, Mesh& mesh);

}  // namespace geomesh
