// optimizeTetrahedra: improves poor tetrahedra by edge removal, 2-3 swaps and smoothing.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

struct TetOptimizerStats {
  std::size_t edgeRemovals = 0;  // rings of tetrahedra around an edge retriangulated
  std::size_t faceSwaps = 0;     // 2-3 flips
  std::size_t nodeMoves = 0;     // interior nodes smoothed
};

// Faces and edges inside a volume that its tetrahedra must keep: the triangles of the surfaces
// and the segments of the curves embedded in it.
struct KeptInside {
  std::vector<std::array<NodeIndex, 3>> triangles;
  std::vector<std::array<NodeIndex, 2>> segments;
  std::vector<NodeIndex> fixedNodes = {};  // nodes of the volume that stay where they are
};

// The volume mesher improves the tetrahedra below this gamma, or below Mesh.OptimizeThreshold
// when that is higher: the reference's default threshold (0.3) leaves a mean gamma a little
// under what this one reaches for a modest cost.
inline constexpr double kOptimizeBelowAtLeast = 0.45;
// Without optimization, tetrahedra under this gamma are still repaired: nearly flat ones are
// not valid elements.
inline constexpr double kFlatBelow = 1e-3;

// Improves the tetrahedra of a volume whose quality (gamma) is below `threshold`, by edge
// removal, 2-3 face swaps and smoothing of the volume's own nodes. Faces with a single
// tetrahedron (the boundary), the faces and edges in `kept` (and the edges of those faces), and
// nodes not classified on the volume never change; every accepted change keeps all tetrahedra
// positively oriented (exact test) and raises the minimum quality of the tetrahedra it
// replaces. Deterministic: no node is added or renumbered.
TetOptimizerStats optimizeTetrahedra(Mesh& mesh, EntityId volume, double threshold,
                                     const KeptInside& kept = {});

// The same on a volume's own arrays: `tets` (4 indices into `points` each) are replaced, and
// the points flagged movable may move; the kept faces and segments are in the same indices.
TetOptimizerStats optimizeTetrahedra(std::vector<Vec3>& points, std::vector<char> movable,
                                     std::vector<std::uint32_t>& tets, double threshold,
                                     std::span<const std::array<std::uint32_t, 3>> keptFaces,
                                     std::span<const std::array<std::uint32_t, 2>> keptSegments);

}  // namespace geomesh
