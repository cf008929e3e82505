// MSH 4.1 sections: $Entities, $Nodes and $Elements in per-entity blocks.
#include <cstdlib>

#include "io/msh_read_state.h"

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

// A piece of a partitioned file: its parent and partitions, then an entity's fields. It is
// read as an entity of its own, which holds its nodes and elements.
void readPartitionedEntity(MshDecoder& in, MshReadState& state, int dim) {
  const int tag = in.integer();
  if (tag < 0) in.fail("invalid entity tag " + std::to_string(tag));
  const int parentDim = in.integer();
  in.integer();  // parent tag
  if (parentDim < 0 || parentDim > 3)
    in.fail("invalid parent dimension " + std::to_string(parentDim));
  tagList(in);  // partitions
  if (state.model.contains({dim, tag}))
    in.fail("partition entity " + std::to_string(tag) + " is defined twice");
  readEntityAfterTag(in, state, dim, tag);
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
  state.model.clear();
  state.physicalMembers.clear();
  in.size();  // number of partitions
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
