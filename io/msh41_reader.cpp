// MSH 4.1 sections: $Entities, $Nodes and $Elements in per-entity blocks.
#include <algorithm>
#include <cstdlib>
#include <utility>

#include "io/msh_read_state.h"
#include "mesh/partition/curve_chains.h"

namespace geomesh {

namespace {

// A count read from the file, checked against what the remaining input could hold so that a
// corrupt count fails at once instead of driving a long loop.
std::uint64_t count(MshDecoder& in, std::size_t minBytesEach) {
  const std::uint64_t n = in.size();
  if (minBytesEach > 0 && n > in.remaining() / minBytesEach)
    in.fail("count " + std::to_string(n) + " exceeds the size of the file");
  return n;
}

std::vector<int> tagList(MshDecoder& in) {
  const std::uint64_t n = count(in, 2);
  std::vector<int> tags;
  for (std::uint64_t i = 0; i < n; ++i) tags.push_back(in.integer());
  return tags;
}

void readEntityAfterTag(MshDecoder& in, MshReadState& state, int dim, int tag);

void readEntity(MshDecoder& in, MshReadState& state, int dim) {
  const int tag = in.integer();
  if (tag < 0) in.fail("invalid entity tag " + std::to_string(tag));  // 0 is a tag too
  readEntityAfterTag(in, state, dim, tag);
}

// A piece of a partitioned file: its parent, partitions, box, groups and bounding pieces.
void readPartitionedEntity(MshDecoder& in, MshReadState& state, int dim) {
  PartitionEntity piece;
  piece.id = {dim, in.integer()};
  if (piece.id.tag < 0) in.fail("invalid entity tag " + std::to_string(piece.id.tag));
  piece.parent.dim = in.integer();
  piece.parent.tag = in.integer();
  if (piece.parent.dim < dim || piece.parent.dim > 3 || !state.model.contains(piece.parent))
    in.fail("partition entity " + std::to_string(piece.id.tag) + " has no parent entity (" +
            std::to_string(piece.parent.dim) + ", " + std::to_string(piece.parent.tag) + ")");
  if (state.model.contains(piece.id) || state.mesh.find(piece.id))
    in.fail("partition entity " + std::to_string(piece.id.tag) + " has the tag of another entity");
  piece.partitions = tagList(in);
  for (int i = 0; i < (dim > 0 ? 6 : 3); ++i) in.real();  // the box: derived, not stored
  piece.physicals = tagList(in);
  for (int group : piece.physicals) state.addToPhysical(dim, group, piece.id.tag);
  if (dim > 0) piece.boundary = tagList(in);
  state.mesh.entity(piece.id);  // holds the piece's nodes and elements while the file is read
  state.pieces.push_back(std::move(piece));
}

void readEntityAfterTag(MshDecoder& in, MshReadState& state, int dim, int tag) {
  Vec3 min{in.real(), in.real(), in.real()};
  if (dim > 0)
    for (int i = 0; i < 3; ++i) in.real();  // the box's upper corner: derived, not stored
  for (int group : tagList(in)) state.addToPhysical(dim, group, tag);
  if (dim == 0) {
    state.model.addPoint(ModelPoint{tag, min, 0});
    return;
  }
  std::vector<int> bounding = tagList(in);
  if (dim == 1) {
    const int start = bounding.empty() ? 0 : std::abs(bounding.front());
    const int end = bounding.size() < 2 ? start : std::abs(bounding[1]);
    state.model.addCurve(ModelCurve{tag, start, end, nullptr});
  } else if (dim == 2) {
    state.model.addSurface(ModelSurface{tag, {std::move(bounding)}, nullptr, {}, {}});
  } else {
    state.model.addVolume(ModelVolume{tag, {std::move(bounding)}});
  }
}

void readNodeBlock(MshDecoder& in, MshReadState& state) {
  const int dim = in.integer();
  MshReadState::checkDimension(in, dim);
  const int tag = in.integer();
  const int parametric = in.integer();
  if (parametric != 0 && parametric != 1) in.fail("invalid parametric flag");
  const std::uint64_t n = count(in, 2);
  EntityMesh& em = state.mesh.entity({dim, tag});
  const std::size_t first = em.nodes.size();
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t nodeTag = in.size();
    if (nodeTag == 0) in.fail("node tags start at 1");
    const NodeIndex index = static_cast<NodeIndex>(state.mesh.nodeCount() + i);
    if (!state.nodeIndex.emplace(nodeTag, index).second)
      in.fail("node " + std::to_string(nodeTag) + " is defined twice");
    em.nodes.push_back(index);
  }
  const int uvCount = parametric ? dim : 0;
  for (std::size_t i = first; i < em.nodes.size(); ++i) {
    const Vec3 xyz{in.real(), in.real(), in.real()};
    state.mesh.addNode(xyz);
    for (int k = 0; k < uvCount; ++k) {
      const double uv = in.real();
      if (dim < 3) em.parametric.push_back(uv);
    }
  }
}

void readElementBlock(MshDecoder& in, MshReadState& state) {
  const int dim = in.integer();
  MshReadState::checkDimension(in, dim);
  const int tag = in.integer();
  const ElementType type = MshReadState::elementType(in, in.integer());
  if (dimension(type) != dim)
    in.fail(std::string(elementName(type)) + " elements on an entity of dimension " +
            std::to_string(dim));
  const std::uint64_t n = count(in, 2 * (1 + nodeCount(type)));
  ElementBlock& block = state.mesh.entity({dim, tag}).block(type);
  for (std::uint64_t i = 0; i < n; ++i) {
    in.size();  // element tag: elements are renumbered
    for (int k = 0; k < nodeCount(type); ++k) block.nodes.push_back(state.node(in, in.size()));
  }
}

}  // namespace

void readMsh41Entities(MshDecoder& in, MshReadState& state) {
  std::uint64_t counts[4];
  for (std::uint64_t& c : counts) c = count(in, 8);
  for (int dim = 0; dim < 4; ++dim)
    for (std::uint64_t i = 0; i < counts[dim]; ++i) readEntity(in, state, dim);
  expectSectionEnd(in, "$EndEntities");
}

// The pieces replace the model's entities: they hold every node and element, carry the
// physical groups, and bound each other.
void readMsh41PartitionedEntities(MshDecoder& in, MshReadState& state) {
  const std::uint64_t partitions = in.size();
  if (partitions == 0 || partitions > 1u << 30) in.fail("invalid number of partitions");
  state.partitionCount = static_cast<int>(partitions);
  const std::uint64_t ghosts = count(in, 8);
  for (std::uint64_t i = 0; i < ghosts; ++i) {
    in.integer();  // ghost entity tag
    in.integer();  // its partition
  }
  std::uint64_t counts[4];
  for (std::uint64_t& c : counts) c = count(in, 8);
  for (int dim = 0; dim < 4; ++dim)
    for (std::uint64_t i = 0; i < counts[dim]; ++i) readPartitionedEntity(in, state, dim);
  expectSectionEnd(in, "$EndPartitionedEntities");
}

// Elements of a piece of the same dimension as its parent are the parent's; a piece inside a
// higher-dimensional parent (an interface) gives it its nodes and keeps its own elements.
void attachPartitions(MshReadState& state) {
  if (state.pieces.empty()) return;
  MeshPartitions partitions;
  partitions.count = state.partitionCount;
  for (PartitionEntity& piece : state.pieces) {
    if (EntityMesh* held = state.mesh.findMutable(piece.id)) {
      piece.nodes = std::move(held->nodes);
      piece.blocks = std::move(held->blocks);
    }
    EntityMesh& parent = state.mesh.entity(piece.parent);
    parent.nodes.insert(parent.nodes.end(), piece.nodes.begin(), piece.nodes.end());
    if (piece.parent.dim == piece.id.dim)
      for (const ElementBlock& b : piece.blocks) {
        ElementBlock& into = parent.block(b.type);
        into.nodes.insert(into.nodes.end(), b.nodes.begin(), b.nodes.end());
      }
    state.mesh.eraseEntity(piece.id);
    partitions.entities.push_back(std::move(piece));
  }
  // A curve's lines come back piece by piece: put them in order along it again.
  for (const auto& [tag, curve] : state.model.curves()) {
    EntityMesh* lines = state.mesh.findMutable({1, tag});
    const EntityMesh* start = state.mesh.find({0, curve.startPoint});
    if (!lines || !start || start->nodes.empty()) continue;
    for (ElementBlock& b : lines->blocks) orderAlongCurve(b, start->nodes.front());
  }
  // Groups of pieces alone (made per partition) belong to the partitions, not to the model.
  for (auto it = state.physicalMembers.begin(); it != state.physicalMembers.end();) {
    const bool ofPieces =
        !it->second.empty() && std::none_of(it->second.begin(), it->second.end(), [&](int tag) {
          return state.model.contains({it->first.dim, tag});
        });
    std::vector<int>& members = it->second;
    if (!ofPieces) {
      std::erase_if(members, [&](int tag) { return !state.model.contains({it->first.dim, tag}); });
      ++it;
      continue;
    }
    auto name = state.physicalNames.find(it->first);
    partitions.physicalGroups.push_back({it->first.dim, it->first.tag,
                                         name == state.physicalNames.end() ? "" : name->second,
                                         it->second});
    if (name != state.physicalNames.end()) state.physicalNames.erase(name);
    it = state.physicalMembers.erase(it);
  }
  state.mesh.setPartitions(std::move(partitions));
}

void readMsh41Nodes(MshDecoder& in, MshReadState& state) {
  const std::uint64_t blocks = count(in, 8);
  const std::uint64_t total = in.size();
  in.size();  // smallest and largest tags: not needed
  in.size();
  const std::size_t before = state.mesh.nodeCount();
  for (std::uint64_t b = 0; b < blocks; ++b) readNodeBlock(in, state);
  if (state.mesh.nodeCount() - before != total)
    in.fail("the node blocks hold " + std::to_string(state.mesh.nodeCount() - before) +
            " nodes, not " + std::to_string(total));
  expectSectionEnd(in, "$EndNodes");
}

void readMsh41Elements(MshDecoder& in, MshReadState& state) {
  const std::uint64_t blocks = count(in, 8);
  const std::uint64_t total = in.size();
  in.size();
  in.size();
  const std::size_t before = state.mesh.elementCount(-1);
  for (std::uint64_t b = 0; b < blocks; ++b) readElementBlock(in, state);
  if (state.mesh.elementCount(-1) - before != total)
    in.fail("the element blocks hold " + std::to_string(state.mesh.elementCount(-1) - before) +
            " elements, not " + std::to_string(total));
  expectSectionEnd(in, "$EndElements");
}

}  // namespace geomesh
