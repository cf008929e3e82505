// Medit (Gamma Mesh Format, ASCII .mesh): Vertices, then one section per element keyword, each
// element followed by its reference. Written with references = physical tags (or entity tags);
// read back as one discrete entity and one physical group per dimension and reference.
#include <istream>
#include <iterator>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"
#include "io/msh_content.h"
#include "io/node_order.h"
#include "io/physical_sets.h"
#include "io/real_text.h"

namespace geomesh {

namespace {

// A Medit element keyword: the element type it holds and, for each node it lists, the index
// of the element's node (in MSH order) that goes there.
struct MeditKeyword {
  const char* name;
  ElementType type;
  std::vector<int> fromMsh;
};

// In the order the sections are written. The second-order nodes follow the corners: edge
// middles edge by edge as numbered below, then a quadrangle's centre.
const std::vector<MeditKeyword>& meditKeywords() {
  using T = ElementType;
  auto layout = [](ElementType type, const NodePlaces& centres) {
    return mshNodesAt(type, cornersThen(type, centres));
  };
  NodePlaces quadNodes = quadEdges();
  quadNodes.push_back({0, 1, 2, 3});
  static const std::vector<MeditKeyword> keywords = {
      {"Edges", T::Line2, layout(T::Line2, {})},
      {"EdgesP2", T::Line3, layout(T::Line3, {{0, 1}})},
      {"Triangles", T::Triangle3, layout(T::Triangle3, {})},
      {"TrianglesP2", T::Triangle6, layout(T::Triangle6, triangleEdges())},
      {"Quadrilaterals", T::Quad4, layout(T::Quad4, {})},
      {"QuadrilateralsQ2", T::Quad9, layout(T::Quad9, quadNodes)},
      {"Tetrahedra", T::Tet4, layout(T::Tet4, {})},
      {"TetrahedraP2", T::Tet10, layout(T::Tet10, tetEdges())},
      {"Prisms", T::Prism6, layout(T::Prism6, {})},
      {"Pyramids", T::Pyramid5, layout(T::Pyramid5, {})},
      {"Hexahedra", T::Hex8, layout(T::Hex8, {})},
  };
  return keywords;
}

// Point elements are not written: their nodes are among the vertices.
const MeditKeyword* keywordOf(ElementType type) {
  if (type == ElementType::Point1) return nullptr;
  for (const MeditKeyword& k : meditKeywords())
    if (k.type == type) return &k;
  if (type == ElementType::Hex27 || type == ElementType::Prism18 || type == ElementType::Pyramid14)
    refuseElementType("Medit", type,
                      "the Medit format fixes no node order for its second-order "
                      "hexahedra, prisms and pyramids");
  refuseElementType("Medit", type, "the Medit format has no keyword for them");
}

void writeVertices(std::ostream& out, const Model& model, const Mesh& mesh,
                   const MshContent& content) {
  out << "\nVertices\n" << content.nodeCount << '\n';
  for (const MshNodeBlock& block : content.nodeBlocks) {
    const int ref = physicalOrEntityTag(model, block.entity);
    for (NodeIndex n : block.nodes) {
      const Vec3 p = mesh.node(n);
      for (double v : {p.x, p.y, p.z}) {
        writeShortestReal(out, v);
        out << ' ';
      }
      out << ref << '\n';
    }
  }
}

void writeSection(std::ostream& out, const Model& model, const MshContent& content,
                  const MeditKeyword& keyword) {
  std::size_t count = 0;
  for (const MshElementBlock& b : content.elementBlocks)
    if (b.block->type == keyword.type) count += b.block->size();
  if (count == 0) return;
  out << '\n' << keyword.name << '\n' << count << '\n';
  for (const MshElementBlock& b : content.elementBlocks) {
    if (b.block->type != keyword.type) continue;
    const int ref = physicalOrEntityTag(model, b.entity);
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      const auto nodes = b.block->element(i);
      for (int k : keyword.fromMsh) out << content.nodeTag[nodes[k]] << ' ';
      out << ref << '\n';
    }
  }
}

// ---- Reading ----

// Keywords whose lines are skipped: how many values each line holds (0: the dimension).
const std::map<std::string, int, std::less<>>& skippedKeywords() {
  static const std::map<std::string, int, std::less<>> skipped = {
      {"Corners", 1},          {"RequiredVertices", 1},  {"Ridges", 1},
      {"RequiredEdges", 1},    {"RequiredTriangles", 1}, {"RequiredQuadrilaterals", 1},
      {"NormalAtVertices", 2}, {"TangentAtVertices", 2}, {"Normals", 0},
      {"Tangents", 0},
  };
  return skipped;
}

struct MeditReader {
  MeditReader(MeshScanner& scanner, Mesh& target) : in(scanner), mesh(target) {}

  MeshScanner& in;
  Mesh& mesh;
  int spaceDim = 0;
  std::size_t vertexCount = 0;
  std::set<EntityId> entities;  // every (dim, reference) met

  // A count, checked against what the rest of the file could hold.
  std::uint64_t count(std::size_t valuesEach) {
    const auto n = in.number<std::uint64_t>("a count");
    if (n > in.remaining() / (2 * valuesEach))
      in.fail("count " + std::to_string(n) + " exceeds the size of the file");
    return n;
  }

  void readVertices() {
    if (spaceDim == 0) in.fail("Vertices before Dimension");
    if (vertexCount != 0) in.fail("a second Vertices section");
    const std::uint64_t n = count(spaceDim + 1);
    mesh.reserveNodes(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      Vec3 p{in.real(), in.real(), 0};
      if (spaceDim == 3) p.z = in.real();
      in.number<long long>("a vertex reference");
      mesh.addNode(p);
    }
    vertexCount = n;
  }

  void readElements(const MeditKeyword& keyword) {
    const int nodes = nodeCount(keyword.type);
    const std::uint64_t n = count(nodes + 1);
    std::vector<NodeIndex> element(nodes);
    for (std::uint64_t i = 0; i < n; ++i) {
      for (int k : keyword.fromMsh) {
        const auto v = in.number<std::uint64_t>("a vertex number");
        if (v == 0 || v > vertexCount)
          in.fail("vertex " + std::to_string(v) + " does not exist (" +
                  std::to_string(vertexCount) + " vertices)");
        element[k] = static_cast<NodeIndex>(v - 1);
      }
      const int ref = in.number<int>("an element reference");
      if (ref < 0) in.fail("negative reference " + std::to_string(ref));
      const EntityId entity{dimension(keyword.type), ref};
      entities.insert(entity);
      ElementBlock& block = mesh.entity(entity).block(keyword.type);
      block.nodes.insert(block.nodes.end(), element.begin(), element.end());
    }
  }

  void skipLines(std::string_view keyword, int valuesEach) {
    const int values = valuesEach == 0 ? spaceDim : valuesEach;
    if (values == 0) in.fail(std::string(keyword) + " before Dimension");
    const std::uint64_t n = count(values);
    for (std::uint64_t i = 0; i < n * values; ++i) in.word();
  }

  // Returns false at End.
  bool readSection(std::string_view word) {
    if (word == "End") return false;
    if (word.front() == '#') {
      in.line();
      return true;
    }
    if (word == "MeshVersionFormatted") {
      const int version = in.number<int>("a version");
      if (version < 1 || version > 4) in.fail("unsupported version " + std::to_string(version));
    } else if (word == "Dimension") {
      spaceDim = in.number<int>("a dimension");
      if (spaceDim != 2 && spaceDim != 3)
        in.fail("unsupported dimension " + std::to_string(spaceDim));
    } else if (word == "Vertices") {
      readVertices();
    } else if (const auto skipped = skippedKeywords().find(word);
               skipped != skippedKeywords().end()) {
      skipLines(word, skipped->second);
    } else {
      const MeditKeyword* keyword = nullptr;
      for (const MeditKeyword& k : meditKeywords())
        if (word == k.name) keyword = &k;
      if (!keyword) in.fail("unsupported keyword '" + std::string(word.substr(0, 40)) + "'");
      readElements(*keyword);
    }
    return true;
  }

  std::vector<PhysicalGroup> groups() const {
    std::vector<PhysicalGroup> out;
    for (const EntityId id : entities)
      if (id.tag > 0) out.push_back({id.dim, id.tag, "", {id.tag}});
    return out;
  }
};

}  // namespace

// Named by the mesh row of io/formats.cpp. Saves what an MSH file would; every element's
// reference is its physical group's tag (the first one) or, outside groups, its entity's tag.
void writeMedit(std::ostream& out, const Model& model, const Mesh& mesh,
                const MeshWriteOptions& options) {
  const MshContent content = selectMshContent(model, mesh, options.saveAll);
  for (const MshElementBlock& b : content.elementBlocks) keywordOf(b.block->type);
  out << "MeshVersionFormatted 2\n\nDimension 3\n";
  writeVertices(out, model, mesh, content);
  for (const MeditKeyword& keyword : meditKeywords()) writeSection(out, model, content, keyword);
  out << "\nEnd\n";
}

// Each (dimension, reference) of the file's elements becomes a discrete entity of that tag and,
// for references above 0, an unnamed physical group of that tag. Vertex references are not
// kept; vertices no element uses are dropped.
void readMedit(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  readReplacing(model, mesh, [&] {
    MeshScanner scanner(data, name);
    MeditReader reader(scanner, mesh);
    if (scanner.atEnd()) scanner.fail("empty file");
    while (!scanner.atEnd() && reader.readSection(scanner.word())) {
    }
    addDiscreteEntities(model, mesh, reader.groups());
  });
}

}  // namespace geomesh
