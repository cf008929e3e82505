// VolumePlc: what TetGen tetrahedralizes for one volume, its shells and what is embedded in it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/core/mesh_options.h"

namespace geomesh {

using PlcTriangle = std::array<int, 3>;  // local indices into VolumePlc::nodes
using PlcSegment = std::array<int, 2>;

// The piecewise linear complex of a volume, with its own compact node numbering: the triangles
// of its shells (outer shell first), then those of the surfaces embedded in it; the segments
// of the embedded curves that are not already triangle edges; the embedded points that are not
// already nodes of either. Every piece must appear in the tetrahedra as it is here.
struct VolumePlc {
  std::vector<NodeIndex> nodes;  // local -> mesh node
  std::vector<PlcTriangle> triangles;
  std::vector<std::size_t> shellStart;  // first triangle of each shell
  std::size_t shellEnd = 0;             // the embedded surfaces' triangles start here
  std::vector<int> surfaceOf;           // per triangle
  std::vector<PlcSegment> segments;
  std::vector<int> curveOf;  // per segment
  std::vector<int> points;   // local node of each embedded point
  std::vector<int> pointOf;  // per point, its tag
  // Quadrangles of the shells' surfaces (recombined or layered), which no tetrahedron can
  // have as a face: addPyramids stands a pyramid on each and replaces it by the pyramid's
  // four side triangles.
  std::vector<std::array<int, 4>> quads;
  std::vector<int> quadSurfaceOf;
  std::vector<std::size_t> quadShellOf;

  bool isEmbedded(std::size_t triangle) const { return triangle >= shellEnd; }
  std::size_t shellEndOf(std::size_t shell) const {
    return shell + 1 < shellStart.size() ? shellStart[shell + 1] : shellEnd;
  }
};

// The shells' triangles (and quadrangles) and the embedded entities' triangles, segments and
// points of a volume, from their meshes in `mesh`. Throws MeshError naming the volume when one
// of them has no mesh or one that is not made of 3-node triangles or 4-node quadrangles
// (shells), 3-node triangles (embedded surfaces) or 2-node lines (curves).
VolumePlc collectVolumePlc(const Model& model, const ModelVolume& volume, const Mesh& mesh);

// Target size at each node of the complex, within the allowed range: at a node of the shells
// or of an embedded surface, the mean length of its triangle edges; at another node (of an
// embedded curve or point), the size at the nearest node of a surface, as the reference leaves
// the tetrahedra around those unrefined.
std::vector<double> plcNodeSizes(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                 const MeshOptions& options);

// The complex's triangles from `first` on (all by default; plc.shellEnd for the embedded
// surfaces'), and its segments, as unsigned local indices: the form the Delaunay kernel and
// the optimizer take.
std::vector<std::array<std::uint32_t, 3>> plcTriangles(const VolumePlc& plc, std::size_t first = 0);
std::vector<std::array<std::uint32_t, 2>> plcSegments(const VolumePlc& plc);

// Renumbers the complex's nodes by i -> i * stride mod n, with the stride the first integer
// from `start` coprime with n, so that TetGen meets the points in another order; `xyz` and
// `sizes` follow.
void renumberPlc(VolumePlc& plc, std::vector<Vec3>& xyz, std::vector<double>& sizes,
                 std::size_t start);

}  // namespace geomesh
