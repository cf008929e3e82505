// STL reader, ASCII or binary. Each solid of an ASCII file becomes one discrete surface (tags
// 1, 2, ... in the order of the solids; a binary file is one solid) of triangles. Vertices with
// exactly the same coordinates are merged into one node, in the whole file: solids that touch
// share their nodes; nearly equal coordinates stay apart. Facet normals are not used.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <istream>
#include <iterator>
#include <string>
#include <string_view>
#include <unordered_map>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"

namespace geomesh {

namespace {

constexpr std::size_t kHeaderBytes = 84;  // 80 free bytes and the facet count
constexpr std::size_t kFacetBytes = 50;   // normal, 3 vertices (12 floats), attribute count

// Nodes by exact coordinates (-0 and +0 being the same coordinate).
class NodeMerger {
 public:
  explicit NodeMerger(Mesh& mesh) : mesh_(mesh) {}
  NodeIndex node(Vec3 p) {
    const Key key{bits(p.x), bits(p.y), bits(p.z)};
    const auto [it, added] = nodes_.try_emplace(key, static_cast<NodeIndex>(mesh_.nodeCount()));
    if (added) mesh_.addNode(p);
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      const std::uint64_t mixed =
          k[0] * 0x9E3779B97F4A7C15ull ^ k[1] * 0xC2B2AE3D27D4EB4Full ^ k[2];
      return std::hash<std::uint64_t>()(mixed);
    }
  };
  static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v + 0.0); }

  Mesh& mesh_;
  std::unordered_map<Key, NodeIndex, KeyHash> nodes_;
};

// Keywords are compared in lower case: some writers shout them.
void expect(MeshScanner& in, std::string_view word, std::string_view why = "") {
  const std::string_view found = in.word();
  if (lowercase(found) != word)
    in.fail("expected '" + std::string(word) + "', found '" + std::string(found.substr(0, 40)) +
            "'" + std::string(why));
}

Vec3 readVector(MeshScanner& in) { return {in.real(), in.real(), in.real()}; }

// One "facet normal ... endfacet" whose first word has been read.
void readAsciiFacet(MeshScanner& in, NodeMerger& nodes, ElementBlock& block) {
  expect(in, "normal");
  readVector(in);
  expect(in, "outer");
  expect(in, "loop");
  for (int k = 0; k < 3; ++k) {
    expect(in, "vertex", ": a facet has 3 vertices");
    block.nodes.push_back(nodes.node(readVector(in)));
  }
  if (lowercase(in.peekWord()) == "vertex") in.fail("a facet with more than 3 vertices");
  expect(in, "endloop");
  expect(in, "endfacet");
}

void readAscii(MeshScanner& in, Mesh& mesh) {
  NodeMerger nodes(mesh);
  for (int tag = 1; !in.atEnd(); ++tag) {
    expect(in, "solid");
    if (in.hasLine()) in.line();  // the solid's name
    ElementBlock block{ElementType::Triangle3, {}};
    for (std::string word = lowercase(in.word()); word != "endsolid";
         word = lowercase(in.word())) {
      if (word != "facet")
        in.fail("expected 'facet' or 'endsolid', found '" + std::string(word.substr(0, 40)) +
                "'");
      readAsciiFacet(in, nodes, block);
    }
    if (in.hasLine()) in.line();
    if (block.size() > 0) mesh.entity({2, tag}).block(ElementType::Triangle3) = std::move(block);
  }
}

// The little-endian count after the 80-byte header (the data holds at least 84 bytes).
std::uint32_t facetCount(std::string_view data) {
  std::uint32_t n = 0;
  for (int k = 3; k >= 0; --k) n = n << 8 | static_cast<unsigned char>(data[80 + k]);
  return n;
}

void readBinary(std::string_view data, const std::string& name, Mesh& mesh) {
  MeshScanner in(data, name);
  in.skip(kHeaderBytes);
  NodeMerger nodes(mesh);
  ElementBlock block{ElementType::Triangle3, {}};
  const std::uint32_t n = facetCount(data);
  for (std::uint32_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) in.raw<float>(std::endian::little);  // the normal
    for (int v = 0; v < 3; ++v) {
      Vec3 p;
      for (double* c : {&p.x, &p.y, &p.z}) *c = in.raw<float>(std::endian::little);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw MeshReadError(name + ": binary facet " + std::to_string(i + 1) + " (byte " +
                            std::to_string(kHeaderBytes + i * kFacetBytes) +
                            ") has a non-finite coordinate");
      block.nodes.push_back(nodes.node(p));
    }
    in.raw<std::uint16_t>(std::endian::little);
  }
  if (n > 0) mesh.entity({2, 1}).block(ElementType::Triangle3) = std::move(block);
}

bool startsWithSolid(std::string_view data) {
  const std::size_t start = data.find_first_not_of(" \t\r\n");
  return start != std::string_view::npos && lowercase(data.substr(start, 5)) == "solid";
}

// Text when it starts with "solid" and has no NUL byte (the attribute counts of binary facets
// almost always have some, and so may the header); binary otherwise, whose size must then be
// exactly that of the facet count the header gives (a shorter one with NUL bytes is told of as
// a binary file cut short, by the byte and facet where its data stops).
bool isBinary(std::string_view data, const std::string& name) {
  if (startsWithSolid(data) && data.find('\0') == std::string_view::npos) return false;
  if (data.size() < kHeaderBytes)
    throw MeshReadError(name + ":1: not an STL file: no 'solid' at the start, and " +
                        std::to_string(data.size()) + " bytes are too few for a binary one");
  const std::uint64_t n = facetCount(data);
  const std::uint64_t expected = kHeaderBytes + n * kFacetBytes;
  if (data.size() == expected) return true;
  // Too short, with the NUL bytes of binary data: a binary file cut off.
  if (data.size() < expected && data.find('\0') != std::string_view::npos) {
    const std::size_t facet = (data.size() - kHeaderBytes) / kFacetBytes + 1;  // from 1
    throw MeshReadError(name + ": binary STL truncated at byte " + std::to_string(data.size()) +
                        " (facet " + std::to_string(facet) + " of " + std::to_string(n) +
                        "): its header gives " + std::to_string(n) + " facets, which take " +
                        std::to_string(expected) + " bytes");
  }
  throw MeshReadError(name + ":1: not an ASCII STL file (no 'solid' at the start, or NUL " +
                      "bytes), nor a binary one: its header gives " + std::to_string(n) +
                      " facets, which take " + std::to_string(kHeaderBytes + n * kFacetBytes) +
                      " bytes, but the file has " + std::to_string(data.size()));
}

}  // namespace

// Named by the stl row of io/formats.cpp.
void readStl(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  readReplacing(model, mesh, [&] {
    if (isBinary(data, name)) {
      readBinary(data, name, mesh);
    } else {
      MeshScanner scanner(data, name);
      readAscii(scanner, mesh);
    }
    addDiscreteEntities(model, mesh);
  });
}

}  // namespace geomesh
