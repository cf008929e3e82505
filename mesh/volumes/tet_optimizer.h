// optimizeTetrahedra: improves poor tetrahedra by edge removal, 2-3 swaps and smoothing.
#pragma once

#include <array>
#include <cstddef>
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

// Improves the tetrahedra of a volume whose quality (gamma) is below `threshold`, by edge
// removal, 2-3 face swaps and smoothing of the volume's own nodes. Faces with a single
// tetrahedron (the boundary), the faces and edges in `kept` (and the edges of those faces), and
// nodes not classified on the volume never change; every accepted change keeps all tetrahedra
// positively oriented (exact test) and raises the minimum quality of the tetrahedra it
// replaces. Deterministic: no node is added or renumbered.
TetOptimizerStats optimizeTetrahedra(Mesh& mesh, EntityId volume, double threshold,
                                     const KeptInside& kept = {});

}  // namespace geomesh
