// parametrizePatch: a one-to-one map of a disk-like patch of a triangulation (a disk, perhaps
// with holes) to the plane, for remeshing the patch in its parameter plane.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/discrete/triangulation.h"

namespace geomesh {

// A patch of a triangulation mapped to the plane.
struct PatchMap {
  std::vector<std::uint32_t> vertices;  // local vertex -> vertex of the Triangulation
  // The patch's triangles in local vertex indices, same order and orientation as given.
  std::vector<TriangleVertices> triangles;
  std::vector<Vec2> uv;  // per local vertex
  bool planar = false;  // the patch is plane and uv is its orthogonal projection onto its plane
  // When planar: the plane's point of uv (0, 0) and its unit axes, uv = ((p - origin).axisU,
  // (p - origin).axisV).
  Vec3 origin{}, axisU{}, axisV{};
};

struct ParametrizationResult {
  std::optional<PatchMap> map;
  std::string failure;  // why there is no map (empty when map has a value)
};

// Maps the triangles `triangles` (indices into t.triangles; a connected patch) to the plane
// one-to-one. `loops`: its boundary as closed vertex cycles (first vertex not repeated), each run
// with the patch on its left; loops[0] is the outer boundary.
//
// A plane patch (every vertex within 1e-6 of the patch's size from its least-squares plane)
// whose orthogonal projection folds no triangle gets that projection, planar = true. Any other
// gets a convex-combination map (Floater's mean value weights): loops[0] on the unit circle by
// chord length, counter-clockwise, so that uv triangles keep the orientation of the 3D ones seen
// from their normal; each hole closed for the solve by a fan of virtual triangles around one
// virtual vertex. Fails when the patch is not genus 0 with at least one boundary loop (V - E + F
// must equal 2 - loops.size()), when a triangle has non-positive signed area in uv, or when the
// ratio of the largest to the smallest uv-area/3D-area over the triangles exceeds 1e8 (triangles
// of zero 3D area are left out of that ratio). Deterministic.
ParametrizationResult parametrizePatch(const Triangulation& t,
                                       std::span<const std::uint32_t> triangles,
                                       std::span<const std::vector<std::uint32_t>> loops);

}  // namespace geomesh
