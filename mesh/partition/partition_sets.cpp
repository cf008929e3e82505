// PartitionSetIndex: partitions of elements from the top-dimensional ones they bound, of nodes
// from the elements around them, and the facets where the partitions change.
#include "mesh/partition/partition_sets.h"

#include <algorithm>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "mesh/high_order/reference_element.h"

namespace geomesh {

int PartitionSets::intern(std::vector<int> partitions) {
  std::sort(partitions.begin(), partitions.end());
  partitions.erase(std::unique(partitions.begin(), partitions.end()), partitions.end());
  const auto [it, added] = ids_.try_emplace(partitions, static_cast<int>(sets_.size()));
  if (added) sets_.push_back(std::move(partitions));
  return it->second;
}

std::size_t FacetHash::operator()(const FacetKey& key) const {
  std::uint64_t h = 1469598103934665603ull;
  for (NodeIndex v : key) h = (h ^ v) * 1099511628211ull;
  return static_cast<std::size_t>(h);
}

FacetKey facetKey(std::span<const NodeIndex> corners) {
  FacetKey key;
  key.fill(kNoNode);
  const std::size_t n = std::min<std::size_t>(corners.size(), key.size());
  for (std::size_t i = 0; i < n; ++i) {  // insertion sort of at most four corners
    std::size_t j = i;
    for (; j > 0 && key[j - 1] > corners[i]; --j) key[j] = key[j - 1];
    key[j] = corners[i];
  }
  return key;
}

const std::vector<std::vector<int>>& facetsOf(ElementFamily family) {
  static const std::vector<std::vector<int>> kFacets[] = {
      {},                                            // point
      {{0}, {1}},                                    // line
      {{0, 1}, {1, 2}, {2, 0}},                      // triangle
      {{0, 1}, {1, 2}, {2, 3}, {3, 0}},              // quadrangle
      {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}},  // tetrahedron
      {{0, 3, 2, 1},
       {0, 1, 5, 4},
       {0, 4, 7, 3},  // hexahedron
       {1, 2, 6, 5},
       {2, 3, 7, 6},
       {4, 5, 6, 7}},
      {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}},  // prism
      {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}},        // pyramid
  };
  return kFacets[static_cast<int>(family)];
}

namespace {

// The (corner, weight) pairs that name a node's place, sorted so that two elements naming the
// same place agree whatever their own corner order.
using PlaceName = std::vector<std::pair<int, int>>;

PlaceName placeName(const NodePlace& place, const std::vector<int>& cornerMap) {
  PlaceName name;
  for (int c = 0; c < place.cornerCount; ++c)
    name.emplace_back(cornerMap[place.corners[c]], place.weights[c] * 1000 / place.total);
  std::sort(name.begin(), name.end());
  return name;
}

FacetNodes buildFacetNodes(ElementType type, const std::vector<int>& facet) {
  const ElementFamily facetFamily = facet.size() == 1   ? ElementFamily::Point
                                    : facet.size() == 2 ? ElementFamily::Line
                                    : facet.size() == 3 ? ElementFamily::Triangle
                                                        : ElementFamily::Quad;
  const ElementType facetType = facet.size() == 1
                                    ? ElementType::Point1
                                    : *elementTypeOf(facetFamily, order(type), isSerendipity(type));
  const ReferenceElement& element = referenceElement(type);
  std::vector<int> identity(vertexCount(type));
  for (int v = 0; v < vertexCount(type); ++v) identity[v] = v;
  std::map<PlaceName, int> byPlace;
  for (std::size_t n = 0; n < element.places.size(); ++n)
    byPlace.emplace(placeName(element.places[n], identity), static_cast<int>(n));
  FacetNodes result{facetType, {}};
  const ReferenceElement& side = referenceElement(facetType);
  for (const NodePlace& place : side.places) {
    const auto it = byPlace.find(placeName(place, facet));
    if (it == byPlace.end())
      throw std::logic_error(std::string("no node of ") + elementName(type) + " on its facet");
    result.nodes.push_back(it->second);
  }
  return result;
}

}  // namespace

const FacetNodes& facetNodes(ElementType type, std::size_t facetIndex) {
  static std::mutex guard;
  static std::map<std::pair<ElementType, std::size_t>, FacetNodes> cache;
  const std::lock_guard lock(guard);
  const auto key = std::make_pair(type, facetIndex);
  auto it = cache.find(key);
  if (it == cache.end())
    it = cache.emplace(key, buildFacetNodes(type, facetsOf(family(type))[facetIndex])).first;
  return it->second;
}

PartitionSetIndex::PartitionSetIndex(const Mesh& mesh, const TopElements& top,
                                     const std::vector<int>& topPartition, bool createTopology)
    : mesh_(mesh) {
  classifyNodes();
  buildTopIncidence(top);
  computeElementSets(top, topPartition);
  computeNodeSets(topPartition);
  computeNodeDims(createTopology);
  if (createTopology) {
    makeInterfaceElements(top.dim);
    makeInterfacePoints();
  }
}

void PartitionSetIndex::classifyNodes() {
  nodeEntity.assign(mesh_.nodeCount(), EntityId{-1, 0});
  for (const auto& [id, em] : mesh_.entities())
    for (NodeIndex n : em.nodes)
      if (n < nodeEntity.size()) nodeEntity[n] = id;
}

void PartitionSetIndex::buildTopIncidence(const TopElements& top) {
  topOffset_.assign(mesh_.nodeCount() + 1, 0);
  for (const TopElements::Ref& r : top.elements)
    for (NodeIndex n : r.block->element(r.index)) ++topOffset_[n + 1];
  for (std::size_t n = 0; n < mesh_.nodeCount(); ++n) topOffset_[n + 1] += topOffset_[n];
  topAround_.resize(topOffset_.back());
  std::vector<std::size_t> fill(topOffset_.begin(), topOffset_.end() - 1);
  for (std::uint32_t t = 0; t < top.elements.size(); ++t)
    for (NodeIndex n : top.elements[t].block->element(top.elements[t].index))
      topAround_[fill[n]++] = t;
}

// A lower element lies in the partitions of the top elements holding all its corners.
int PartitionSetIndex::lowerElementSet(std::span<const NodeIndex> corners,
                                       const std::vector<int>& topPartition,
                                       const TopElements& top) {
  std::vector<int> parts;
  const NodeIndex first = corners[0];
  for (std::size_t k = topOffset_[first]; k < topOffset_[first + 1]; ++k) {
    const TopElements::Ref& r = top.elements[topAround_[k]];
    const auto around = r.block->element(r.index).first(vertexCount(r.block->type));
    const bool holds = std::all_of(corners.begin(), corners.end(), [&](NodeIndex c) {
      return std::find(around.begin(), around.end(), c) != around.end();
    });
    if (holds) parts.push_back(topPartition[topAround_[k]]);
  }
  if (parts.empty())  // not a facet of any top element: the partitions around its corners
    for (NodeIndex c : corners)
      for (std::size_t k = topOffset_[c]; k < topOffset_[c + 1]; ++k)
        parts.push_back(topPartition[topAround_[k]]);
  if (parts.empty()) parts.push_back(1);
  return sets.intern(std::move(parts));
}

void PartitionSetIndex::computeElementSets(const TopElements& top,
                                           const std::vector<int>& topPartition) {
  std::size_t t = 0;
  std::map<int, int> single;  // partition -> the set holding it alone
  for (const auto& [id, em] : mesh_.entities())
    for (const ElementBlock& b : em.blocks)
      for (std::size_t i = 0; i < b.size(); ++i) {
        if (dimension(b.type) == top.dim) {
          const int p = topPartition[t++];
          auto [it, added] = single.try_emplace(p, 0);
          if (added) it->second = sets.intern({p});
          elementSet_.push_back(it->second);
        } else {
          const auto corners = b.element(i).first(vertexCount(b.type));
          elementSet_.push_back(lowerElementSet(corners, topPartition, top));
        }
      }
}

void PartitionSetIndex::computeNodeSets(const std::vector<int>& topPartition) {
  std::vector<std::vector<int>> parts(mesh_.nodeCount());
  for (NodeIndex n = 0; n < mesh_.nodeCount(); ++n)
    for (std::size_t k = topOffset_[n]; k < topOffset_[n + 1]; ++k)
      parts[n].push_back(topPartition[topAround_[k]]);
  forEachModelElement([&](EntityId, const ElementBlock& b, std::size_t i, int set) {
    for (NodeIndex n : b.element(i))
      if (topOffset_[n] == topOffset_[n + 1])
        parts[n].insert(parts[n].end(), sets[set].begin(), sets[set].end());
  });
  nodeSet.resize(mesh_.nodeCount());
  for (NodeIndex n = 0; n < mesh_.nodeCount(); ++n) {
    if (parts[n].empty()) parts[n].push_back(1);
    nodeSet[n] = sets.intern(std::move(parts[n]));
  }
}

// A node lies on a piece of its entity's dimension, lowered by each partition around it beyond
// those of the entity's elements around it. Without topology, nodes take the partitions of an
// element of their entity with the fewest, so they join a piece holding elements.
void PartitionSetIndex::computeNodeDims(bool createTopology) {
  const int none = std::numeric_limits<int>::max();
  std::vector<int> fewest(mesh_.nodeCount(), none), fewestSet(mesh_.nodeCount(), -1);
  forEachModelElement([&](EntityId e, const ElementBlock& b, std::size_t i, int set) {
    const int size = static_cast<int>(sets[set].size());
    for (NodeIndex n : b.element(i))
      if (nodeEntity[n] == e && size < fewest[n]) fewest[n] = size, fewestSet[n] = set;
  });
  nodeDim.assign(mesh_.nodeCount(), 0);
  for (NodeIndex n = 0; n < mesh_.nodeCount(); ++n) {
    if (!held(n)) continue;
    const int d = nodeEntity[n].dim;
    if (!createTopology) {
      nodeDim[n] = d;
      if (fewestSet[n] >= 0) nodeSet[n] = fewestSet[n];
      continue;
    }
    const int size = static_cast<int>(sets[nodeSet[n]].size());
    const int base = fewest[n] == none ? size : fewest[n];
    nodeDim[n] = std::max(0, d - (size - base));
  }
}

namespace {

// Where the cells of one parent meet: the partition sets on each side of a facet.
struct FacetSides {
  int firstSet = -1;
  bool differ = false;
  std::vector<int> partitions;
  ElementType type = ElementType::Line2;
  std::vector<NodeIndex> nodes;  // the facet as an element of `type`, seen from the first side
};

}  // namespace

// Facets between cells of one parent in different partitions become elements of one dimension
// lower, unless the mesh already has an element there; from the top dimension down to curves.
void PartitionSetIndex::makeInterfaceElements(int topDim) {
  const auto onInterface = [&](NodeIndex n) { return sets[nodeSet[n]].size() >= 2; };
  std::unordered_set<FacetKey, FacetHash> existing;
  forEachModelElement([&](EntityId, const ElementBlock& b, std::size_t i, int) {
    const auto corners = b.element(i).first(vertexCount(b.type));
    if (dimension(b.type) >= 1 && dimension(b.type) < topDim &&
        std::all_of(corners.begin(), corners.end(), onInterface))
      existing.insert(facetKey(corners));
  });
  for (int d = topDim; d >= 2; --d) {
    std::map<EntityId, std::unordered_map<FacetKey, FacetSides, FacetHash>> byParent;
    const auto addCell = [&](EntityId parent, ElementType type, const NodeIndex* nodes, int set) {
      auto& facets = byParent[parent];
      const auto& all = facetsOf(family(type));
      for (std::size_t f = 0; f < all.size(); ++f) {
        const std::vector<int>& facet = all[f];
        std::array<NodeIndex, 4> corners{};
        bool candidate = true;
        for (std::size_t k = 0; k < facet.size(); ++k) {
          corners[k] = nodes[facet[k]];
          candidate = candidate && onInterface(corners[k]);
        }
        if (!candidate) continue;
        FacetSides& sides = facets[facetKey(std::span(corners.data(), facet.size()))];
        if (sides.firstSet < 0) {
          const FacetNodes& local = facetNodes(type, f);
          sides.firstSet = set;
          sides.type = local.type;
          for (int k : local.nodes) sides.nodes.push_back(nodes[k]);
        } else if (set != sides.firstSet) {
          sides.differ = true;
        }
        sides.partitions.insert(sides.partitions.end(), sets[set].begin(), sets[set].end());
      }
    };
    forEachModelElement([&](EntityId e, const ElementBlock& b, std::size_t i, int set) {
      if (e.dim == d && dimension(b.type) == d) addCell(e, b.type, b.element(i).data(), set);
    });
    for (const InterfaceElement& f : interfaces)
      if (f.dim == d) addCell(f.parent, f.type, f.nodes.data(), f.set);
    for (auto& [parent, facets] : byParent) {
      std::vector<std::pair<FacetKey, FacetSides*>> made;
      for (auto& [key, sides] : facets)
        if (sides.differ && !existing.contains(key)) made.emplace_back(key, &sides);
      std::sort(made.begin(), made.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (auto& [key, sides] : made)
        interfaces.push_back({d - 1, parent, sets.intern(std::move(sides->partitions)), sides->type,
                              std::move(sides->nodes)});
    }
  }
}

// Nodes that are points of the partition topology inside a curve, surface or volume get a
// point element.
void PartitionSetIndex::makeInterfacePoints() {
  for (NodeIndex n = 0; n < mesh_.nodeCount(); ++n)
    if (held(n) && nodeDim[n] == 0 && nodeEntity[n].dim > 0)
      interfaces.push_back({0, nodeEntity[n], nodeSet[n], ElementType::Point1, {n}});
}

}  // namespace geomesh
