// Choosing a partition for each element of the mesh's highest dimension: by METIS on the
// elements' dual graph, or by slices of the bounding box (the SimplePartition plugin).
#pragma once

#include <array>
#include <vector>

#include "mesh/core/mesh.h"

namespace geomesh {

// The elements of the highest dimension that has elements, in the order of the entities
// (dim, tag), their blocks and the elements in each block.
struct TopElements {
  int dim = -1;
  struct Ref {
    const ElementBlock* block;
    std::size_t index;
  };
  std::vector<Ref> elements;
};
TopElements topElements(const Mesh& mesh);

// Mesh.Metis* and Mesh.Partition*Weight, with the reference's codes.
struct MetisSettings {
  int algorithm = 1;         // 1 recursive bisection, 2 k-way
  int objective = 1;         // 1 edge cut, 2 communication volume
  int edgeMatching = 2;      // 1 random, 2 sorted heavy-edge
  int refinement = 2;        // 1 FM, 2 greedy, 3 two-sided node FM, 4 one-sided node FM
  double maxImbalance = -1;  // allowed load imbalance (1.03: 3%); -1: METIS's default
  int minConnectivity = -1;  // 1: minimize the partitions' connectivity; -1: METIS's default
  // Load weight per element family (ElementFamily order); -1 or 0: weight 1.
  std::array<int, 8> familyWeights = {-1, -1, -1, -1, -1, -1, -1, -1};
};

// Partition numbers (from 1) of `top.elements`, split into `count` parts. Throws
// std::invalid_argument when count exceeds the number of elements, std::runtime_error when
// METIS fails.
std::vector<int> metisPartition(const TopElements& top, int count, const MetisSettings& settings);

// Slices along x, y and z of the box of the elements' centroids: partition
// 1 + i + nx * (j + ny * k) for the slice (i, j, k) holding the element's centroid.
std::vector<int> slicePartition(const Mesh& mesh, const TopElements& top,
                                std::array<int, 3> slices);

}  // namespace geomesh
