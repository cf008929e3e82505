// shrinkLayer: where a boundary layer must be thinner than asked, so that it stays valid.
#pragma once

#include <cstddef>
#include <span>
#include <unordered_map>
#include <vector>

#include "mesh/core/mesh.h"

namespace geomesh {

// The faces a layer grows from: triangles and quadrangles (or segments, for layers in the
// plane), each `sizes[f]` nodes in `nodes`, with the signed height of the thickest layer
// grown from it (`heights[f]`; negative: against the normals).
struct LayerFaces {
  std::vector<NodeIndex> nodes;
  std::vector<unsigned char> sizes;
  std::vector<double> heights;
};

// What shrinkLayer decided: a factor in (0, 1] per node (1 where the layer keeps its height),
// the number of nodes below 1, and the smallest factor with its node.
struct LayerShrinking {
  std::unordered_map<NodeIndex, double> factor;
  std::size_t shrunk = 0;
  double smallest = 1;
  NodeIndex where = 0;
  Vec3 at;  // where's position
};

// Factors for a layer grown from the faces along the unit `normals` of their nodes, each
// node's column as high as the thickest face holding it asks (and its way), so that (1) two
// parts of the layer that grow towards each other stop before they meet: each column at
// most 0.45 of the gap between the two nodes, and (2) no element of the layer is inverted:
// every corner of every prism (or hexahedron) over a face keeps a positive Jacobian, the
// columns of a face that breaks this shortened by 0.7 at a time.
LayerShrinking shrinkLayer(const Mesh& mesh, const LayerFaces& faces,
                           const std::unordered_map<NodeIndex, Vec3>& normals);

}  // namespace geomesh
