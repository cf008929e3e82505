// buildPartitions: partition sets of elements and nodes, interface elements, then the pieces
// with their tags, boundaries and physical groups.
#include "mesh/partition/partition_topology.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "mesh/partition/curve_chains.h"
#include "mesh/partition/partition_sets.h"

namespace geomesh {

namespace {

// A piece before it has a tag: its dimension, parent and partition set, and for a point
// inside a curve, surface or volume its node (-1 otherwise).
using PieceKey = std::tuple<int, int, int, int, std::int64_t>;

PieceKey pieceKey(int dim, EntityId parent, int set, std::int64_t node = -1) {
  return {dim, parent.dim, parent.tag, set, node};
}

ElementBlock& blockOf(PartitionEntity& piece, ElementType type) {
  for (ElementBlock& b : piece.blocks)
    if (b.type == type) return b;
  piece.blocks.push_back({type, {}});
  return piece.blocks.back();
}

class PieceAssembler {
 public:
  PieceAssembler(const Model& model, const Mesh& mesh, const PartitionSetIndex& index)
      : model_(model), mesh_(mesh), index_(index) {}

  MeshPartitions assemble(int count, bool createPhysicals) {
    collectKeys();
    placeNodes();
    placeElements();
    splitCurves();
    numberPieces();
    findBoundaries();
    MeshPartitions result;
    result.count = count;
    assignPhysicals(result, createPhysicals);
    result.entities = std::move(pieces_);
    return result;
  }

 private:
  PieceKey nodeKey(NodeIndex n) const {
    const EntityId parent = index_.nodeEntity[n];
    const int dim = index_.nodeDim[n];
    return pieceKey(dim, parent, index_.nodeSet[n],
                    dim == 0 && parent.dim > 0 ? std::int64_t{n} : -1);
  }

  int pieceOf(const PieceKey& key) {
    const auto [it, added] = keys_.try_emplace(key, static_cast<int>(pieces_.size()));
    if (added) {
      const auto [dim, parentDim, parentTag, set, node] = key;
      PartitionEntity piece;
      piece.id = {dim, 0};
      piece.parent = {parentDim, parentTag};
      piece.partitions = index_.sets[set];
      pieces_.push_back(std::move(piece));
    }
    return it->second;
  }

  void collectKeys() {
    std::set<PieceKey> keys;
    for (NodeIndex n = 0; n < index_.nodeEntity.size(); ++n)
      if (index_.held(n)) keys.insert(nodeKey(n));
    index_.forEachModelElement([&](EntityId e, const ElementBlock&, std::size_t, int set) {
      keys.insert(pieceKey(e.dim, e, set));
    });
    for (const InterfaceElement& f : index_.interfaces)
      keys.insert(pieceKey(f.dim, f.parent, f.set, f.dim == 0 ? std::int64_t{f.nodes[0]} : -1));
    for (const PieceKey& key : keys) pieceOf(key);
  }

  void placeNodes() {
    nodePiece_.assign(index_.nodeEntity.size(), -1);
    for (NodeIndex n = 0; n < index_.nodeEntity.size(); ++n) {
      if (!index_.held(n)) continue;
      nodePiece_[n] = keys_.at(nodeKey(n));
      pieces_[nodePiece_[n]].nodes.push_back(n);
    }
  }

  void placeElements() {
    index_.forEachModelElement([&](EntityId e, const ElementBlock& b, std::size_t i, int set) {
      const auto nodes = b.element(i);
      auto& target = blockOf(pieces_[keys_.at(pieceKey(e.dim, e, set))], b.type).nodes;
      target.insert(target.end(), nodes.begin(), nodes.end());
    });
    for (const InterfaceElement& f : index_.interfaces) {
      const PieceKey key =
          pieceKey(f.dim, f.parent, f.set, f.dim == 0 ? std::int64_t{f.nodes[0]} : -1);
      auto& target = blockOf(pieces_[keys_.at(key)], f.type).nodes;
      target.insert(target.end(), f.nodes.begin(), f.nodes.end());
    }
  }

  // A curve piece is one chain of lines from point to point: pieces with several chains are
  // split, and nodes on no line of theirs become points.
  void splitCurves() {
    const std::size_t before = pieces_.size();
    for (std::size_t p = 0; p < before; ++p)
      if (pieces_[p].id.dim == 1) splitCurve(static_cast<int>(p));
  }

  void splitCurve(int self) {
    std::vector<ElementBlock> chains;
    for (const ElementBlock& b : pieces_[self].blocks) {
      // Lines of a model curve stay in its order and direction; those made on interfaces are
      // walked into order.
      auto split = splitIntoChains(
          b, [&](NodeIndex n) { return nodePiece_[n] == self; }, pieces_[self].parent.dim != 1);
      std::move(split.begin(), split.end(), std::back_inserter(chains));
    }
    const std::vector<NodeIndex> nodes = std::exchange(pieces_[self].nodes, {});
    pieces_[self].blocks.clear();
    for (std::size_t c = 0; c < chains.size(); ++c) {
      int target = self;
      if (c > 0) {
        target = static_cast<int>(pieces_.size());
        PartitionEntity copy;
        copy.id = {1, 0};
        copy.parent = pieces_[self].parent;
        copy.partitions = pieces_[self].partitions;
        pieces_.push_back(std::move(copy));
      }
      std::vector<NodeIndex> inner;
      for (NodeIndex n : chains[c].nodes)
        if (nodePiece_[n] == self) inner.push_back(n);
      std::sort(inner.begin(), inner.end());
      inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
      for (NodeIndex n : inner) nodePiece_[n] = target;
      pieces_[target].nodes = std::move(inner);
      pieces_[target].blocks.push_back(std::move(chains[c]));
    }
    // Nodes still marked `self` but not in the first chain are on no line: they become points
    // (collected first, as making points grows pieces_).
    const std::vector<NodeIndex>& first = pieces_[self].nodes;
    std::vector<NodeIndex> lost;
    for (NodeIndex n : nodes)
      if (nodePiece_[n] == self && !std::binary_search(first.begin(), first.end(), n))
        lost.push_back(n);
    for (NodeIndex n : lost) makePoint(n);
  }

  void makePoint(NodeIndex n) {
    const int p = pieceOf(pieceKey(0, index_.nodeEntity[n], index_.nodeSet[n], n));
    pieces_[p].nodes.push_back(n);
    blockOf(pieces_[p], ElementType::Point1).nodes.push_back(n);
    nodePiece_[n] = p;
  }

  // Tags follow the model's of each dimension, pieces ordered by parent, partition set and
  // first node.
  void numberPieces() {
    std::vector<int> order(pieces_.size());
    std::iota(order.begin(), order.end(), 0);
    const auto firstNode = [&](const PartitionEntity& p) -> NodeIndex {
      if (!p.nodes.empty()) return p.nodes.front();
      for (const ElementBlock& b : p.blocks)
        if (!b.nodes.empty()) return b.nodes.front();
      return kNoNode;
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const PartitionEntity& x = pieces_[a];
      const PartitionEntity& y = pieces_[b];
      return std::tie(x.id.dim, x.parent.dim, x.parent.tag, x.partitions) !=
                     std::tie(y.id.dim, y.parent.dim, y.parent.tag, y.partitions)
                 ? std::tie(x.id.dim, x.parent.dim, x.parent.tag, x.partitions) <
                       std::tie(y.id.dim, y.parent.dim, y.parent.tag, y.partitions)
                 : firstNode(x) < firstNode(y);
    });
    std::vector<int> moved(pieces_.size());
    std::vector<PartitionEntity> sorted;
    std::array<int, 4> next{};
    for (int d = 0; d < 4; ++d) next[d] = maxTag(d);
    for (int old : order) {
      moved[old] = static_cast<int>(sorted.size());
      sorted.push_back(std::move(pieces_[old]));
      sorted.back().id.tag = ++next[sorted.back().id.dim];
    }
    pieces_ = std::move(sorted);
    for (int& p : nodePiece_)
      if (p >= 0) p = moved[p];
  }

  int maxTag(int dim) const {
    int tag = model_.maxTag(dim);
    for (const auto& [id, em] : mesh_.entities())
      if (id.dim == dim) tag = std::max(tag, id.tag);
    return tag;
  }

  // A curve is bounded by the points at the ends of its chain (start, then minus the end); a
  // surface or volume by the pieces one dimension lower holding its elements' facets (twice,
  // with both signs, for a seam).
  void findBoundaries() {
    int top = 0;
    for (const PartitionEntity& piece : pieces_) top = std::max(top, piece.id.dim);
    std::unordered_map<FacetKey, int, FacetHash> owner;  // elements that can bound a piece
    for (std::size_t p = 0; p < pieces_.size(); ++p)
      for (const ElementBlock& b : pieces_[p].blocks)
        if (dimension(b.type) >= 1 && dimension(b.type) < top)
          for (std::size_t i = 0; i < b.size(); ++i)
            owner.emplace(facetKey(b.element(i).first(vertexCount(b.type))), static_cast<int>(p));
    for (PartitionEntity& piece : pieces_) {
      if (piece.id.dim == 1) {
        piece.boundary = chainEnds(piece);
        continue;
      }
      // Facets of the bounding pieces this piece's elements touch, and how often: a facet met
      // from both sides lies on a seam, whose piece is then listed twice, as loops list seams.
      std::map<FacetKey, int> touched;
      for (const ElementBlock& b : piece.blocks) {
        if (dimension(b.type) != piece.id.dim || piece.id.dim == 0) continue;
        for (std::size_t i = 0; i < b.size(); ++i) touchFacets(piece, b, i, owner, touched);
      }
      std::map<int, bool> bounding;  // tag -> seam
      for (const auto& [facet, count] : touched) {
        const int tag = pieces_[owner.at(facet)].id.tag;
        bounding[tag] = bounding[tag] || count > 1;
      }
      piece.boundary.clear();
      for (const auto& [tag, seam] : bounding) {
        piece.boundary.push_back(tag);
        if (seam) piece.boundary.push_back(-tag);
      }
    }
  }

  std::vector<int> chainEnds(const PartitionEntity& piece) const {
    if (piece.blocks.empty() || piece.blocks.front().size() == 0) return {};
    const ElementBlock& chain = piece.blocks.front();
    const int start = nodePiece_[chain.element(0)[0]];
    const int end = nodePiece_[chain.element(chain.size() - 1)[1]];
    std::vector<int> ends;
    if (start >= 0 && pieces_[start].id.dim == 0) ends.push_back(pieces_[start].id.tag);
    if (end >= 0 && pieces_[end].id.dim == 0) ends.push_back(-pieces_[end].id.tag);
    return ends;
  }

  void touchFacets(const PartitionEntity& piece, const ElementBlock& b, std::size_t i,
                   const std::unordered_map<FacetKey, int, FacetHash>& owner,
                   std::map<FacetKey, int>& touched) const {
    const auto element = b.element(i);
    for (const std::vector<int>& facet : facetsOf(family(b.type))) {
      std::array<NodeIndex, 4> corners{};
      bool interior = false;
      for (std::size_t k = 0; k < facet.size(); ++k) {
        corners[k] = element[facet[k]];
        const int p = nodePiece_[corners[k]];
        interior = interior || (p >= 0 && pieces_[p].id.dim == piece.id.dim);
      }
      if (interior) continue;
      const FacetKey key = facetKey(std::span(corners.data(), facet.size()));
      const auto it = owner.find(key);
      if (it != owner.end() && pieces_[it->second].id.dim == piece.id.dim - 1) ++touched[key];
    }
  }

  void assignPhysicals(MeshPartitions& result, bool createPhysicals) {
    if (!createPhysicals) {
      for (PartitionEntity& piece : pieces_)
        if (piece.parent.dim == piece.id.dim) piece.physicals = model_.physicalTagsOf(piece.parent);
      return;
    }
    int nextTag = 0;
    for (const auto& [id, group] : model_.physicalGroups()) nextTag = std::max(nextTag, id.tag);
    std::map<std::tuple<int, std::vector<int>, int>, std::size_t> groupOf;
    for (int dim = 3; dim >= 0; --dim)
      for (PartitionEntity& piece : pieces_) {
        if (piece.id.dim != dim) continue;
        std::vector<int> parents = model_.physicalTagsOf(piece.parent);
        if (parents.empty()) parents.push_back(0);
        for (int physical : parents) {
          const auto key = std::make_tuple(dim, piece.partitions, physical);
          auto [it, added] = groupOf.emplace(key, result.physicalGroups.size());
          if (added)
            result.physicalGroups.push_back(
                {dim, ++nextTag, groupName(piece.partitions, physical, dim), {}});
          PhysicalGroup& group = result.physicalGroups[it->second];
          group.entities.push_back(piece.id.tag);
          piece.physicals.push_back(group.tag);
        }
      }
  }

  static std::string groupName(const std::vector<int>& partitions, int physical, int dim) {
    std::string list;
    for (int p : partitions) list += (list.empty() ? "" : ",") + std::to_string(p);
    return "_part{" + list + "}_physical{" + std::to_string(physical) + "}_dim{" +
           std::to_string(dim) + "}";
  }

  const Model& model_;
  const Mesh& mesh_;
  const PartitionSetIndex& index_;
  std::map<PieceKey, int> keys_;
  std::vector<PartitionEntity> pieces_;
  std::vector<int> nodePiece_;
};

}  // namespace

MeshPartitions buildPartitions(const Model& model, const Mesh& mesh, const TopElements& top,
                               const std::vector<int>& topPartition, int count,
                               const PartitionTopologyOptions& options) {
  const PartitionSetIndex index(mesh, top, topPartition, options.createTopology);
  return PieceAssembler(model, mesh, index).assemble(count, options.createPhysicals);
}

}  // namespace geomesh
