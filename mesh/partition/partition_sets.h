// The partitions around every node and element of a partitioned mesh, and the elements that
// the interfaces between partitions get.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "mesh/core/mesh.h"
#include "mesh/partition/element_partition.h"

namespace geomesh {

// Ascending partition sets, each stored once and named by its index.
class PartitionSets {
 public:
  int intern(std::vector<int> partitions);
  const std::vector<int>& operator[](int id) const { return sets_[id]; }

 private:
  std::map<std::vector<int>, int> ids_;
  std::vector<std::vector<int>> sets_;
};

// The corners of a facet, sorted; unused places hold kNoNode.
inline constexpr NodeIndex kNoNode = 0xffffffffu;
using FacetKey = std::array<NodeIndex, 4>;
struct FacetHash {
  std::size_t operator()(const FacetKey& key) const;
};
FacetKey facetKey(std::span<const NodeIndex> corners);
// The facets of an element family as lists of corner positions, oriented outwards.
const std::vector<std::vector<int>>& facetsOf(ElementFamily family);

// The local node indices of an element of type `type` that make up its facet with corners
// `facet` (positions among its vertices), in the node order of the facet's own type, which is
// returned too: Triangle6 for a face of a Tet10.
struct FacetNodes {
  ElementType type;
  std::vector<int> nodes;
};
const FacetNodes& facetNodes(ElementType type, std::size_t facetIndex);

// An element made on an interface between partitions inside `parent`.
struct InterfaceElement {
  int dim = 0;
  EntityId parent;
  int set = 0;
  ElementType type = ElementType::Line2;
  std::vector<NodeIndex> nodes;
};

// Partition sets of the mesh's nodes and elements, computed once.
class PartitionSetIndex {
 public:
  PartitionSetIndex(const Mesh& mesh, const TopElements& top, const std::vector<int>& topPartition,
                    bool createTopology);

  bool held(NodeIndex n) const { return nodeEntity[n].dim >= 0; }
  // Calls f(entity, block, index in block, set) for every element of the entity meshes.
  template <class F>
  void forEachModelElement(F f) const {
    std::size_t k = 0;
    for (const auto& [id, em] : mesh_.entities())
      for (const ElementBlock& b : em.blocks)
        for (std::size_t i = 0; i < b.size(); ++i) f(id, b, i, elementSet_[k++]);
  }

  PartitionSets sets;
  std::vector<EntityId> nodeEntity;  // the entity holding each node; dim -1 when none
  std::vector<int> nodeSet;          // partitions around each node
  std::vector<int> nodeDim;          // dimension of the piece each node lies on
  std::vector<InterfaceElement> interfaces;

 private:
  void classifyNodes();
  void buildTopIncidence(const TopElements& top);
  void computeElementSets(const TopElements& top, const std::vector<int>& topPartition);
  int lowerElementSet(std::span<const NodeIndex> corners, const std::vector<int>& topPartition,
                      const TopElements& top);
  void computeNodeSets(const std::vector<int>& topPartition);
  void computeNodeDims(bool createTopology);
  void makeInterfaceElements(int topDim);
  void makeInterfacePoints();

  const Mesh& mesh_;
  std::vector<int> elementSet_;         // per element, in forEachModelElement order
  std::vector<std::size_t> topOffset_;  // CSR: top elements around each node
  std::vector<std::uint32_t> topAround_;
};

}  // namespace geomesh
