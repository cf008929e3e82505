// MSH 2.2 (and 3.0) sections, and the MSH 1.0 ones they grew from: a flat node list and a flat
// element list whose elements carry their physical group and entity tags. Nodes are classified
// afterwards, on the lowest-dimensional entity whose elements use them.
#include <algorithm>
#include <array>

#include "io/msh_read_state.h"

namespace geomesh {

namespace {

// The most nodes an element of any type has (125, the hexahedron of order 4).
constexpr int kMaxElementNodes = [] {
  int most = 0;
  for (const ElementTypeInfo& info : kElementTypes) most = std::max<int>(most, info.nodes);
  return most;
}();

// The count that opens a section is text, even in binary files.
std::uint64_t headerCount(MshDecoder& in, std::size_t minBytesEach) {
  const bool binary = in.binary();
  in.setBinary(false);
  const std::uint64_t n = in.size();
  in.line();  // the line break before binary data
  in.setBinary(binary);
  if (n > in.remaining() / minBytesEach)
    in.fail("count " + std::to_string(n) + " exceeds the size of the file");
  return n;
}

struct ElementHeader {
  ElementType type;
  int physical = 0;
  int entity = 0;
};

ElementHeader readTags(MshDecoder& in, ElementType type, int tagCount) {
  if (tagCount < 0 || tagCount > 1000) in.fail("invalid tag count " + std::to_string(tagCount));
  ElementHeader header{type};
  for (int k = 0; k < tagCount; ++k) {
    const int tag = in.integer();
    if (k == 0) header.physical = tag;
    if (k == 1) header.entity = tag;
  }
  return header;
}

// An element of an entity in several physical groups is written once per group, each copy
// right after the previous one: a repeat of the block's last element is not added again.
void addElement(MshDecoder& in, MshReadState& state, const ElementHeader& h) {
  const EntityId entity{dimension(h.type), h.entity};
  const int n = nodeCount(h.type);
  std::array<NodeIndex, kMaxElementNodes> nodes;
  for (int k = 0; k < n; ++k) {
    const int tag = in.integer();
    if (tag <= 0) in.fail("invalid node tag " + std::to_string(tag));
    nodes[k] = state.node(in, static_cast<std::uint64_t>(tag));
  }
  ElementBlock& block = state.mesh.entity(entity).block(h.type);
  const bool repeat =
      block.size() > 0 && std::equal(nodes.begin(), nodes.begin() + n, block.nodes.end() - n);
  if (!repeat) block.nodes.insert(block.nodes.end(), nodes.begin(), nodes.begin() + n);
  if (h.physical != 0) state.addToPhysical(entity.dim, h.physical, entity.tag);
}

void readTextElements(MshDecoder& in, MshReadState& state, std::uint64_t n) {
  for (std::uint64_t i = 0; i < n; ++i) {
    in.integer();  // element tag: elements are renumbered
    const ElementType type = MshReadState::elementType(in, in.integer());
    addElement(in, state, readTags(in, type, in.integer()));
  }
}

void readBinaryElements(MshDecoder& in, MshReadState& state, std::uint64_t n) {
  for (std::uint64_t read = 0; read < n;) {
    const ElementType type = MshReadState::elementType(in, in.integer());
    const int groupSize = in.integer();
    const int tagCount = in.integer();
    if (groupSize <= 0 || static_cast<std::uint64_t>(groupSize) > n - read)
      in.fail("invalid element group size " + std::to_string(groupSize));
    for (int i = 0; i < groupSize; ++i, ++read) {
      in.integer();
      addElement(in, state, readTags(in, type, tagCount));
    }
  }
}

// A 2.2 file names entities only through its elements: each one becomes a model entity, and
// the node of a point element gives the point's coordinates.
void classifyNodesAndAddEntities(MshReadState& state) {
  std::vector<char> classified(state.mesh.nodeCount(), 0);
  std::vector<EntityId> ids;
  for (const auto& [id, em] : state.mesh.entities()) ids.push_back(id);
  for (EntityId id : ids) {
    EntityMesh& em = state.mesh.entity(id);
    for (const ElementBlock& b : em.blocks)
      for (NodeIndex n : b.nodes)
        if (!classified[n]) {
          classified[n] = 1;
          em.nodes.push_back(n);
        }
    switch (id.dim) {
      case 0: {
        const NodeIndex n = em.blocks.front().nodes.front();
        state.model.addPoint({id.tag, state.mesh.node(n), 0});
        break;
      }
      case 1: state.model.addCurve({id.tag, 0, 0, nullptr}); break;
      case 2: state.model.addSurface({id.tag, {}, nullptr, {}, {}}); break;
      default: state.model.addVolume({id.tag, {}}); break;
    }
  }
}

}  // namespace

namespace {

void readNodeList(MshDecoder& in, MshReadState& state, const char* endMarker) {
  const std::uint64_t n = headerCount(in, 4);
  for (std::uint64_t i = 0; i < n; ++i) {
    const int tag = in.integer();
    if (tag <= 0) in.fail("invalid node tag " + std::to_string(tag));
    const NodeIndex index = static_cast<NodeIndex>(state.mesh.nodeCount());
    if (!state.nodeIndex.emplace(static_cast<std::uint64_t>(tag), index).second)
      in.fail("node " + std::to_string(tag) + " is defined twice");
    state.mesh.addNode({in.real(), in.real(), in.real()});
  }
  expectSectionEnd(in, endMarker);
}

}  // namespace

void readMsh22Nodes(MshDecoder& in, MshReadState& state) { readNodeList(in, state, "$EndNodes"); }

void readMsh1Nodes(MshDecoder& in, MshReadState& state) {
  if (in.binary()) in.fail("binary MSH 1.0 files do not exist");
  readNodeList(in, state, "$ENDNOD");
}

void readMsh1Elements(MshDecoder& in, MshReadState& state) {
  const std::uint64_t n = headerCount(in, 10);
  for (std::uint64_t i = 0; i < n; ++i) {
    in.integer();  // element tag: elements are renumbered
    const ElementType type = MshReadState::elementType(in, in.integer());
    ElementHeader header{type};
    header.physical = in.integer();
    header.entity = in.integer();
    const int nodes = in.integer();
    if (nodes != nodeCount(type))
      in.fail("an element of type " + std::to_string(static_cast<int>(type)) + " has " +
              std::to_string(nodeCount(type)) + " nodes, not " + std::to_string(nodes));
    addElement(in, state, header);
  }
  expectSectionEnd(in, "$ENDELM");
  classifyNodesAndAddEntities(state);
}

void readMsh22Elements(MshDecoder& in, MshReadState& state) {
  const std::uint64_t n = headerCount(in, 8);
  if (in.binary())
    readBinaryElements(in, state, n);
  else
    readTextElements(in, state, n);
  expectSectionEnd(in, "$EndElements");
  classifyNodesAndAddEntities(state);
}

}  // namespace geomesh
